// `cuelab-cli state SETUP --at T`: every ball's exact state at time T as JSON.

#include "Command.h"
#include "ResultText.h"

namespace cuelab::cli {

Command stateCommand()
{
    Command c;
    c.name = QStringLiteral("state");
    c.help = QStringLiteral("  state SETUP --at T                    Print every ball's exact state at time T as JSON.\n");
    c.options = {{QStringLiteral("at"), QStringLiteral("T"), QStringLiteral("The time <T> of the state to print")}};
    c.run = [](Invocation& in) -> int {
        QString problem;
        const std::optional<double> at = in.seconds(QStringLiteral("at"), false, &problem);
        if (!problem.isEmpty()) return in.usage(problem);
        if (!at) return in.usage(QStringLiteral("state: --at T is required"));
        int status = Success;
        const std::optional<Setup> setup = in.loadSetup(&status);
        if (!setup) return status;
        SimulationResult result;
        const bool finished = in.simulate(*setup, *at, result);
        // Past the end of an unfinished run the state at t is unknown: print nothing rather than a guess.
        if (!finished && result.endTime < *at) return static_cast<int>(SimulationUnfinished);
        in.out() += QByteArray::fromStdString(stateJson(result, *at));
        return finished ? Success : SimulationUnfinished;
    };
    return c;
}

}  // namespace cuelab::cli
