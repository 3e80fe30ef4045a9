// `cuelab-cli code SETUP`: prints the setup's shot code, one line (CONTRACT.md, Extensions version 3,
// "Shot codes"). With --set, the code of the overridden setup. Any SETUP argument of any subcommand
// may be such a code (core/io/ShotCode.h).

#include "Command.h"

#include "ShotCode.h"

namespace cuelab::cli {

Command codeCommand()
{
    Command c;
    c.name = QStringLiteral("code");
    c.help = QStringLiteral("  code SETUP                            Print the setup as a shot code: one line to share\n"
                            "                                        (\"cuelab:1:...\"), taken wherever a SETUP is.\n");
    c.takesMaxEvents = false;
    c.run = [](Invocation& in) -> int {
        int status = Success;
        const std::optional<Setup> setup = in.loadSetup(&status);
        if (!setup) return status;
        in.out() += io::shotCode(*setup).toLatin1() + '\n';
        return Success;
    };
    return c;
}

}  // namespace cuelab::cli
