// `cuelab-cli simulate SETUP [--until T]`: the event log and the final state as JSON.

#include "Command.h"
#include "ResultText.h"

namespace cuelab::cli {

Command simulateCommand()
{
    Command c;
    c.name = QStringLiteral("simulate");
    c.help = QStringLiteral("  simulate SETUP [--until T]            Print the event log and the final state as JSON.\n");
    c.options = {{QStringLiteral("until"), QStringLiteral("T"), QStringLiteral("Stop the simulation at time <T>")}};
    c.run = [](Invocation& in) -> int {
        QString problem;
        const std::optional<double> until = in.seconds(QStringLiteral("until"), false, &problem);
        if (!problem.isEmpty()) return in.usage(problem);
        int status = Success;
        const std::optional<Setup> setup = in.loadSetup(&status);
        if (!setup) return status;
        SimulationResult result;
        const bool finished = in.simulate(*setup, until.value_or(-1.0), result);
        in.out() += QByteArray::fromStdString(simulationJson(result, setup->game ? &*setup->game : nullptr));
        return finished ? Success : SimulationUnfinished;
    };
    return c;
}

}  // namespace cuelab::cli
