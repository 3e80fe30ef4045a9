// `cuelab-cli validate SETUP`: checks the setup; prints nothing on stdout when it is valid. A value
// beyond real play but within the safe bounds (core/setup/RealPlay.h) loads and gets one warning line
// on stderr each; the exit status stays 0 (CONTRACT.md, Extensions version 2).

#include "Command.h"

#include "Refusal.h"
#include "RealPlay.h"

namespace cuelab::cli {

Command validateCommand()
{
    Command c;
    c.name = QStringLiteral("validate");
    c.help = QStringLiteral("  validate SETUP                        Check the setup file; print nothing if it is valid.\n");
    c.takesMaxEvents = false;
    c.run = [](Invocation& in) -> int {
        int status = Success;
        const std::optional<Setup> setup = in.loadSetup(&status);
        if (!setup) return status;
        const std::string name = in.setupName().toStdString();
        for (const SetupWarning& w : setupWarnings(*setup))
            in.err() += "cuelab-cli: warning: " + QByteArray::fromStdString(analysis::refusalMessage(name, w)) + '\n';
        return Success;
    };
    return c;
}

}  // namespace cuelab::cli
