// cuelab-cli: the command-line tool of CONTRACT.md (see Cli.h).

#include "Cli.h"

#include <QCoreApplication>

int main(int argc, char* argv[])
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("cuelab-cli"));
    QCoreApplication::setApplicationVersion(QStringLiteral(CUELAB_VERSION));
    return cuelab::cli::run(QCoreApplication::arguments());
}
