#include "Residual.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace cuelab {

std::vector<bool> selectedBalls(const Recording& recording, const std::string& struckId, BallSelection balls)
{
    std::vector<bool> chosen(recording.balls.size(), false);
    for (std::size_t i = 0; i < recording.balls.size(); ++i) {
        const RecordedBall& b = recording.balls[i];
        const bool struck = b.id == struckId;
        switch (balls) {
        case BallSelection::Struck: chosen[i] = struck || struckId.empty(); break;
        case BallSelection::Moved: chosen[i] = struck || moved(b); break;
        case BallSelection::All: chosen[i] = true; break;
        }
    }
    return chosen;
}

Residual residual(const SimulationResult& result, const Recording& recording, const std::string& struckId,
                  const ResidualOptions& options)
{
    Residual out;
    const std::vector<bool> chosen = selectedBalls(recording, struckId, options.balls);
    double pooled = 0.0;  // m^2, sum of squared distances over the selected balls
    for (std::size_t i = 0; i < recording.balls.size(); ++i) {
        const RecordedBall& b = recording.balls[i];
        BallResidual r;
        r.id = b.id;
        r.selected = chosen[i];
        const int index = result.ballIndex(b.id);
        double sum = 0.0;
        for (const RecordedSample& s : b.samples) {
            if (s.time > options.until) break;
            double d = std::numeric_limits<double>::infinity();
            Vec2 simulated = Vec2::Constant(std::numeric_limits<double>::quiet_NaN());
            if (index >= 0) {
                // stateAt holds a ball's final state beyond the run's end (a run to rest or to `until`).
                const double t = std::clamp(s.time - options.strikeTime, 0.0, result.endTime);
                simulated = result.stateAt(index, t).position;
                d = (simulated - s.position).norm();
            }
            sum += d * d;
            ++r.count;
            if (options.keepSamples) out.samples.push_back({s.time, static_cast<int>(i), s.position, simulated, d});
        }
        r.rmse = r.count > 0 ? std::sqrt(sum / r.count) : 0.0;
        if (r.selected) {
            pooled += sum;
            out.count += r.count;
        }
        out.perBall.push_back(std::move(r));
    }
    out.rmse = out.count > 0 ? std::sqrt(pooled / out.count) : 0.0;
    return out;
}

std::string missingBall(const Recording& recording, const Setup& setup)
{
    for (const RecordedBall& b : recording.balls) {
        bool found = false;
        for (const Ball& ball : setup.balls) found = found || ball.id == b.id;
        if (!found) return b.id;
    }
    return {};
}

std::string residualCsv(const Residual& r, const Recording& recording)
{
    const auto number = [](double v) {
        if (std::isinf(v)) return std::string(v > 0 ? "inf" : "-inf");
        if (std::isnan(v)) return std::string("nan");
        char buffer[32];
        std::snprintf(buffer, sizeof buffer, "%.17g", v);
        return std::string(buffer);
    };
    std::string out = "ball,time_s,recorded_x_m,recorded_y_m,simulated_x_m,simulated_y_m,distance_m\n";
    for (const SampleResidual& s : r.samples) {
        const std::size_t b = static_cast<std::size_t>(s.ball);
        out += (b < recording.balls.size() ? recording.balls[b].id : std::to_string(s.ball)) + ',' + number(s.time) + ',' +
               number(s.recorded.x()) + ',' + number(s.recorded.y()) + ',' + number(s.simulated.x()) + ',' +
               number(s.simulated.y()) + ',' + number(s.distance) + '\n';
    }
    return out;
}

}  // namespace cuelab
