#include "Map.h"

#include <cmath>

namespace cuelab::analysis {

ShotClass classifyShot(const ShotResult& shot)
{
    switch (shot.status) {
    case ShotStatus::Refused: return ShotClass::Refused;
    case ShotStatus::Unfinished: return ShotClass::Unfinished;
    case ShotStatus::Skipped: return ShotClass::Outside;
    case ShotStatus::Simulated: break;
    }
    if (shot.goalMet) return ShotClass::GoalMet;
    if (shot.outcome.struckBallPocketed) return ShotClass::Scratch;
    if (!shot.outcome.firstContact) return ShotClass::NoContact;
    return ShotClass::Missed;
}

std::string_view toString(ShotClass c)
{
    switch (c) {
    case ShotClass::GoalMet: return "meets the goal";
    case ShotClass::Missed: return "misses the goal";
    case ShotClass::NoContact: return "hits no ball";
    case ShotClass::Scratch: return "scratch (struck ball pocketed)";
    case ShotClass::Refused: return "illegal setup";
    case ShotClass::Unfinished: return "run cut short";
    case ShotClass::Outside: return "beyond the miscue limit";
    }
    return "";
}

SweepSpec mapSpec(const SweepSpec& base, const Variation& x, const Variation& y)
{
    SweepSpec spec = base;
    spec.shard = spec.shards = 1;
    spec.variations = {y, x};  // the last varies fastest
    return spec;
}

std::optional<SweepSpec> tipOffsetMapSpec(const SweepSpec& base, int n, double limit)
{
    auto side = Parameter::resolve(base.base, "shot.side");
    auto height = Parameter::resolve(base.base, "shot.height");
    if (!std::holds_alternative<Parameter>(side) || !std::holds_alternative<Parameter>(height)) return std::nullopt;
    const Range range{-limit, limit, n};
    SweepSpec spec = mapSpec(base, Variation{std::get<Parameter>(side), range}, Variation{std::get<Parameter>(height), range});
    // values = {height, side}; a small allowance keeps the cells on the limit circle itself.
    spec.skip = [limit](const std::vector<double>& v) { return std::hypot(v[0], v[1]) > limit * (1.0 + 1e-12); };
    return spec;
}

}  // namespace cuelab::analysis
