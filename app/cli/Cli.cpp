#include "Cli.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QTextStream>

namespace cuelab::cli {

int run(const QStringList& arguments)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral("CueLab's command-line tool."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument(QStringLiteral("command"), QStringLiteral("The command to run."));
    if (!parser.parse(arguments)) {
        QTextStream(stderr) << parser.errorText() << '\n';
        return 2;
    }
    if (parser.isSet(QStringLiteral("help"))) parser.showHelp(0);
    if (parser.isSet(QStringLiteral("version"))) parser.showVersion();
    QTextStream(stderr) << "cuelab-cli: no commands yet; see --help\n";
    return 2;
}

}  // namespace cuelab::cli
