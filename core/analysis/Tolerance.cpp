#include "Tolerance.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace cuelab::analysis {

namespace {

bool meets(const SweepSpec& spec, const std::vector<double>& values)
{
    return runShotWith(spec, values).goalMet;
}

// Bisects between a value that fails and one that meets the goal; returns the last value known to meet it.
double refineEdge(const SweepSpec& spec, double failing, double meeting, int steps, long long& shots,
                  const std::stop_token& stop)
{
    for (int i = 0; i < steps && !stop.stop_requested(); ++i) {
        const double middle = 0.5 * (failing + meeting);
        if (middle == failing || middle == meeting) break;  // no double between them
        ++shots;
        (meets(spec, {middle}) ? meeting : failing) = middle;
    }
    return meeting;
}

}  // namespace

ToleranceScan scanTolerance(const SweepSpec& base, const Parameter& parameter, const ToleranceRequest& request,
                            std::stop_token stop, const std::function<void(long long, long long)>& progress)
{
    ToleranceScan scan;
    scan.key = parameter.key();
    scan.current = parameter.number(base.base);

    SweepSpec spec = base;
    spec.shard = spec.shards = 1;
    if (stop.stop_possible()) spec.simulation.cancel = stop;  // a slow shot ends within a step
    const double from = std::max(request.lowest, scan.current - request.halfSpan);
    const double to = std::min(request.highest, scan.current + request.halfSpan);
    spec.variations = {Variation{parameter, Range{from, to, std::max(1, request.count)}}};
    const long long total = shotCount(spec) + 2LL * request.refineSteps;

    runSweep(
        spec,
        [&](ShotResult& shot) {
            scan.values.push_back(shot.values[0]);
            scan.status.push_back(shot.status);
            scan.met.push_back(shot.goalMet);
            if (progress) progress(static_cast<long long>(scan.values.size()), total);
        },
        stop);
    scan.shots = static_cast<long long>(scan.values.size());
    if (stop.stop_requested() || scan.values.size() != static_cast<std::size_t>(spec.variations[0].range.count))
        return scan;

    spec.variations[0].range = Range{scan.current, scan.current, 1};
    scan.currentMet = meets(spec, {scan.current});
    ++scan.shots;

    // The grid point nearest the current value that meets the goal (the current one when it does).
    const int n = static_cast<int>(scan.values.size());
    int seed = -1;
    for (int i = 0; i < n; ++i) {
        if (!scan.met[static_cast<std::size_t>(i)]) continue;
        if (seed < 0 || std::abs(scan.values[static_cast<std::size_t>(i)] - scan.current) <
                            std::abs(scan.values[static_cast<std::size_t>(seed)] - scan.current))
            seed = i;
    }
    if (seed < 0) return scan;
    scan.found = true;
    int a = seed, b = seed;
    while (a > 0 && scan.met[static_cast<std::size_t>(a - 1)]) --a;
    while (b + 1 < n && scan.met[static_cast<std::size_t>(b + 1)]) ++b;
    scan.lowAtScanEdge = a == 0;
    scan.highAtScanEdge = b == n - 1;
    scan.low = scan.values[static_cast<std::size_t>(a)];
    scan.high = scan.values[static_cast<std::size_t>(b)];
    if (!scan.lowAtScanEdge)
        scan.low = refineEdge(spec, scan.values[static_cast<std::size_t>(a - 1)], scan.low, request.refineSteps,
                              scan.shots, stop);
    if (progress) progress(total - request.refineSteps, total);
    if (!scan.highAtScanEdge)
        scan.high = refineEdge(spec, scan.values[static_cast<std::size_t>(b + 1)], scan.high, request.refineSteps,
                               scan.shots, stop);
    if (progress) progress(total, total);
    if (stop.stop_requested()) scan.found = false;
    return scan;
}

std::string unitOf(const std::string& key)
{
    const auto ends = [&](const char* suffix) {
        const std::string s(suffix);
        return key.size() >= s.size() && key.compare(key.size() - s.size(), s.size(), s) == 0;
    };
    if (ends("heading") || ends("elevation")) return "°";
    if (ends("speed") || ends(".vx") || ends(".vy")) return " m/s";
    if (ends("shot.side") || ends("shot.height")) return " R";
    if (ends(".wx") || ends(".wy") || ends(".wz")) return " rad/s";
    if (ends("mass")) return " kg";
    if (ends(".x") || ends(".y") || ends("radius") || ends("length") || ends("width") || ends("cushion_height"))
        return " m";
    if (ends("max_time") || ends("frame_dt")) return " s";
    if (ends("gravity")) return " m/s²";
    return "";
}

std::string describeWindow(const ToleranceScan& scan, int digits)
{
    if (!scan.found) return "no value in the scanned range meets the goal";
    const std::string unit = unitOf(scan.key);
    char text[256];
    std::snprintf(text, sizeof text, "from %.*f%s to %.*f%s, ±%.*f%s", digits, scan.low, unit.c_str(), digits,
                  scan.high, unit.c_str(), digits, scan.halfWidth(), unit.c_str());
    std::string out(text);
    if (scan.lowAtScanEdge || scan.highAtScanEdge) out += " (reaches the end of the scan)";
    return out;
}

}  // namespace cuelab::analysis
