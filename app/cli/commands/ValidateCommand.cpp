// `cuelab-cli validate SETUP`: checks the setup; prints nothing when it is valid.

#include "Command.h"

namespace cuelab::cli {

Command validateCommand()
{
    Command c;
    c.name = QStringLiteral("validate");
    c.help = QStringLiteral("  validate SETUP                        Check the setup file; print nothing if it is valid.\n");
    c.takesMaxEvents = false;
    c.run = [](Invocation& in) -> int {
        int status = Success;
        return in.loadSetup(&status) ? Success : status;
    };
    return c;
}

}  // namespace cuelab::cli
