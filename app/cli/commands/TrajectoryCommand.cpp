// `cuelab-cli trajectory SETUP [--frame-dt S] [--until T]`: every ball's state per frame and at
// every event, as CSV.

#include "Command.h"
#include "JsonText.h"
#include "ResultText.h"

namespace cuelab::cli {

namespace {

// The most frames `trajectory` prints (a 10-minute run at 60 frames per second has 36000).
constexpr double kMaxFrames = 1e7;

}  // namespace

Command trajectoryCommand()
{
    Command c;
    c.name = QStringLiteral("trajectory");
    c.help = QStringLiteral("  trajectory SETUP [--frame-dt S] [--until T]\n"
                            "                                        Print every ball's state per frame and at every\n"
                            "                                        event as CSV.\n");
    c.options = {{QStringLiteral("frame-dt"), QStringLiteral("S"),
                  QStringLiteral("The frame step <S> of the trajectory (default: the setup's frame_dt)")},
                 {QStringLiteral("until"), QStringLiteral("T"), QStringLiteral("Stop the simulation at time <T>")}};
    c.run = [](Invocation& in) -> int {
        QString problem;
        const std::optional<double> until = in.seconds(QStringLiteral("until"), false, &problem);
        if (!problem.isEmpty()) return in.usage(problem);
        const std::optional<double> frameDtOption = in.seconds(QStringLiteral("frame-dt"), true, &problem);
        if (!problem.isEmpty()) return in.usage(problem);
        int status = Success;
        const std::optional<Setup> setup = in.loadSetup(&status);
        if (!setup) return status;
        SimulationResult result;
        const bool finished = in.simulate(*setup, until.value_or(-1.0), result);
        const double frameDt = frameDtOption.value_or(setup->simulation.frameDt);
        // A frame step far below the run's length would print without end: refuse before printing.
        if (result.endTime / frameDt > kMaxFrames)
            return in.usage(QStringLiteral("trajectory: a frame step of %1 s gives more than %2 frames over %3 s; "
                                           "choose a larger --frame-dt")
                                .arg(QString::fromStdString(io::roundTripNumber(frameDt)))
                                .arg(static_cast<long long>(kMaxFrames))
                                .arg(QString::fromStdString(io::roundTripNumber(result.endTime))));
        in.out() += QByteArray::fromStdString(trajectoryCsv(result, frameDt));
        return finished ? Success : SimulationUnfinished;
    };
    return c;
}

}  // namespace cuelab::cli
