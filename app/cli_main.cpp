// cuelab-cli: the command-line tool of CONTRACT.md.
// Exit status: 0 success, 1 setup refused, 2 usage error, 3 simulation could not finish.

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QTextStream>

int main(int argc, char* argv[])
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("cuelab-cli"));
    QCoreApplication::setApplicationVersion(QStringLiteral(CUELAB_VERSION));

    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral("CueLab's command-line tool."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument(QStringLiteral("command"), QStringLiteral("The command to run."));
    if (!parser.parse(QCoreApplication::arguments())) {
        QTextStream(stderr) << parser.errorText() << '\n';
        return 2;
    }
    if (parser.isSet(QStringLiteral("help"))) parser.showHelp(0);
    if (parser.isSet(QStringLiteral("version"))) parser.showVersion();
    QTextStream(stderr) << "cuelab-cli: no commands yet; see --help\n";
    return 2;
}
