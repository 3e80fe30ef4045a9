// The subcommands of cuelab-cli, in the order of the help text. A new subcommand: a file in
// app/cli/commands/ defining `Command <name>Command()`, declared and listed here (one line each).

#include "Command.h"

namespace cuelab::cli {

Command validateCommand();
Command simulateCommand();
Command stateCommand();
Command trajectoryCommand();
Command explainCommand();
Command compareCommand();
Command sweepCommand();
Command oddsCommand();
Command solveCommand();
Command fitCommand();
Command calibrateCommand();
Command codeCommand();

const QList<Command>& commands()
{
    static const QList<Command> all{
        validateCommand(),
        simulateCommand(),
        stateCommand(),
        trajectoryCommand(),
        explainCommand(),
        compareCommand(),
        sweepCommand(),
        oddsCommand(),
        solveCommand(),
        fitCommand(),
        calibrateCommand(),
        codeCommand(),
    };
    return all;
}

}  // namespace cuelab::cli
