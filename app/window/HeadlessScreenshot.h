#pragma once
// `cuelab --screenshot OUT SETUP [--time T] [--camera top|player|side] [--size WxH]`: renders a
// setup without showing a window. Kept apart from main() so that new formats and options are added
// here, beside the options they read.

class QCommandLineParser;
class QString;

namespace cuelab {

// Adds --screenshot and its options to the parser of the `cuelab` program.
void addScreenshotOptions(QCommandLineParser& parser);

// The first option of --screenshot's own (--time, --camera, --size) given without --screenshot,
// or an empty string: the window would ignore it, so main() refuses it as a usage error.
QString strayScreenshotOption(const QCommandLineParser& parser);

// Prints "cuelab: MESSAGE" on stderr, as every command-line refusal of the window does.
void printCommandLineError(const QString& message);

// Renders what the parsed command line asks for; returns the process's exit status
// (0 written, 1 refused setup or unwritable picture, 2 usage error).
int takeScreenshot(const QCommandLineParser& parser, const QString& out);

}  // namespace cuelab
