#include "RunChecks.h"

#include "Checks.h"
#include "Detection.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace cuelab::soak {

namespace {

constexpr std::array kKinds{FailureKind::EventLimit, FailureKind::NotAtRest, FailureKind::LostStop,
                            FailureKind::Overlap,    FailureKind::Escape,    FailureKind::Energy,
                            FailureKind::Momentum,   FailureKind::Timeline,  FailureKind::Determinism};

std::string number(double v)
{
    char buffer[40];
    std::snprintf(buffer, sizeof buffer, "%.17g", v);
    return buffer;
}

// At most one failure per kind: the first one found.
class Verdict {
public:
    bool has(FailureKind k) const { return seen_[static_cast<std::size_t>(k)]; }
    void add(FailureKind k, std::string message)
    {
        if (has(k)) return;
        seen_[static_cast<std::size_t>(k)] = true;
        failures_.push_back({k, std::move(message)});
    }
    std::vector<Failure> take()
    {
        std::stable_sort(failures_.begin(), failures_.end(),
                         [](const Failure& a, const Failure& b) { return a.kind < b.kind; });
        return std::move(failures_);
    }

private:
    std::array<bool, kKinds.size()> seen_{};
    std::vector<Failure> failures_;
};

// The instants the states are checked at, in time order: every event time, `perGap` instants between
// consecutive distinct event times and `uniform` instants over [0, end_time].
std::vector<double> sampleTimes(const SimulationResult& r, const CheckOptions& o)
{
    std::vector<double> times{0.0, r.endTime};
    for (const Event& e : r.events) times.push_back(e.time);
    std::sort(times.begin(), times.end());
    times.erase(std::unique(times.begin(), times.end()), times.end());
    const std::size_t distinct = times.size();
    for (std::size_t k = 0; k + 1 < distinct; ++k)
        for (int q = 1; q <= o.samplesPerGap; ++q)
            times.push_back(times[k] + (times[k + 1] - times[k]) * q / (o.samplesPerGap + 1));
    for (int k = 1; k < o.uniformSamples; ++k) times.push_back(r.endTime * k / o.uniformSamples);
    std::sort(times.begin(), times.end());
    times.erase(std::unique(times.begin(), times.end()), times.end());
    return times;
}

bool isEventTime(const std::vector<double>& eventTimes, double t)
{
    return std::binary_search(eventTimes.begin(), eventTimes.end(), t);
}

// Places and overlaps at every instant, and the energy from one instant to the next (across an event
// instant: from just before it to just after it).
void checkStates(const SimulationResult& r, const CheckOptions& o, Verdict& v, RunMeasures& m)
{
    const std::size_t n = r.balls.size();
    std::vector<double> pocketedAt(n, kNever);  // the time of each ball's pocket event
    std::vector<int> pocketOf(n, -1);
    std::vector<double> eventTimes;
    for (const Event& e : r.events) {
        eventTimes.push_back(e.time);
        if (e.kind == EventKind::BallPocket && pocketOf[static_cast<std::size_t>(e.balls[0])] < 0) {
            pocketedAt[static_cast<std::size_t>(e.balls[0])] = e.time;
            pocketOf[static_cast<std::size_t>(e.balls[0])] = e.pocket;
        }
    }
    std::sort(eventTimes.begin(), eventTimes.end());
    const double strike = !r.events.empty() && r.events.front().kind == EventKind::CueStrike ? r.events.front().time : -1.0;
    m.initialEnergy = testing::totalEnergy(r, r.statesAt(0.0));
    const double allowed = o.energyTolerance * m.initialEnergy;
    double last = m.initialEnergy, lastTime = 0.0;
    auto energyStep = [&](double e, double t, const char* how) {
        const double rise = e - last;
        m.worstEnergyRise = std::max(m.worstEnergyRise, rise);
        if (rise > allowed)
            v.add(FailureKind::Energy, "the kinetic energy rose by " + number(rise) + " J (" + number(rise / m.initialEnergy) +
                                           " of the shot's) from t = " + number(lastTime) + " to t = " + number(t) + how);
        last = e;
        lastTime = t;
    };
    for (double t : sampleTimes(r, o)) {
        if (t > 0.0 && t != strike && isEventTime(eventTimes, t)) {  // the motion up to the instant
            std::vector<BallState> before(n);
            for (std::size_t i = 0; i < n; ++i) before[i] = testing::stateBefore(r, static_cast<int>(i), t);
            energyStep(testing::totalEnergy(r, before), t, " (just before its events)");
        }
        const std::vector<BallState> s = r.statesAt(t);
        if (t > 0.0) energyStep(testing::totalEnergy(r, s), t, isEventTime(eventTimes, t) ? " (across its events)" : "");
        const double overlap = testing::maxOverlap(r, s);
        m.worstOverlap = std::max(m.worstOverlap, overlap);
        if (overlap > o.overlapTolerance) v.add(FailureKind::Overlap, "an overlap of " + number(overlap) + " m at t = " + number(t));
        for (std::size_t i = 0; i < n; ++i) {
            const double R = r.balls[i].radius;
            if (!isOutOfPlay(s[i].motion) && testing::cushionOverlap(r.table, s[i], R) > o.overlapTolerance)
                continue;  // an overlap with a cushion, reported as such above
            std::string why = testing::placeProblem(r, s[i], R);
            if (why.empty() && s[i].motion == MotionState::Pocketed && !(pocketedAt[i] <= t && pocketOf[i] == s[i].pocket))
                why = "pocketed without a pocket event";
            if (!why.empty())
                v.add(FailureKind::Escape, "ball " + r.balls[i].id + " at t = " + number(t) + " (" + number(s[i].position.x()) +
                                               ", " + number(s[i].position.y()) + "): " + why);
        }
    }
}

void checkEvents(const SimulationResult& r, const CheckOptions& o, Verdict& v, RunMeasures& m)
{
    const double allowed = o.energyTolerance * m.initialEnergy;
    for (std::size_t k = 0; k < r.events.size(); ++k) {
        const Event& e = r.events[k];
        // Every collision begins with the bodies approaching (or pressed together at rest), never
        // with them parting: no collision is found twice. (A held collision may begin from a parting
        // speed so small that the pair would never part by more than kContactTolerance before the
        // cloth presses it back: Detection.cpp; so may a collision solved with a held group.)
        if (isCollision(e.kind) && !(e.approachSpeed > -kRestingSpeed || ((e.held || e.grouped) && e.approachSpeed > -1e-4)))
            v.add(FailureKind::Timeline, "event " + std::to_string(k) + " (" + std::string(toString(e.kind)) + " at t = " +
                                             number(e.time) + ") begins parting at " + number(e.approachSpeed) + " m/s");
        // No event adds energy to the balls it lists (its own and the held group's members it
        // changes, Event::group) beyond 1e-12 of theirs (issue 40): the total between instants
        // (checkStates) hides a rise there behind the other balls' friction. (Plus the rounding of
        // a held group's solve, which is exact to 1e-13 of the group's energy, at most the shot's:
        // HeldContacts.cpp's re-seating; a slow member of a fast group may gain that much.)
        if (e.kind != EventKind::CueStrike) {
            const testing::EventEnergy own = testing::eventEnergy(r, e);
            const double rise = own.after - own.before;
            const double relative = own.before > 0.0 ? rise / own.before : rise > 0.0 ? 1.0 : 0.0;
            if (rise > o.eventEnergyRounding * m.initialEnergy)
                m.worstEventEnergyRise = std::max(m.worstEventEnergyRise, relative);
            if (rise > o.eventEnergyTolerance * own.before + o.eventEnergyRounding * m.initialEnergy)
                v.add(FailureKind::Energy, "event " + std::to_string(k) + " (" + std::string(toString(e.kind)) + " at t = " +
                                               number(e.time) + ") adds " + number(rise) + " J to its " +
                                               std::to_string((e.balls[1] >= 0 ? 2 : 1) + e.group.size()) + " balls (" +
                                               number(own.before > 0.0 ? rise / own.before : 0.0) + " of their energy)");
        }
        if (!isCollision(e.kind) || e.grouped) continue;
        // A collision alone (not solved with a group) never adds energy to its own balls.
        double before = 0.0, after = 0.0;
        const int agents = e.kind == EventKind::BallBall ? 2 : 1;
        for (int a = 0; a < agents; ++a) {
            const Ball& b = r.balls[static_cast<std::size_t>(e.balls[static_cast<std::size_t>(a)])];
            before += kineticEnergy(e.before[static_cast<std::size_t>(a)], b.radius, b.mass);
            after += kineticEnergy(e.after[static_cast<std::size_t>(a)], b.radius, b.mass);
        }
        m.worstEnergyRise = std::max(m.worstEnergyRise, after - before);
        if (after - before > allowed)
            v.add(FailureKind::Energy, "event " + std::to_string(k) + " (" + std::string(toString(e.kind)) + " at t = " +
                                           number(e.time) + ") adds " + number(after - before) + " J to its balls");
        // Friction between two balls is internal: any ball-ball law keeps the pair's momentum. (Not
        // checked with a flying ball: the cloth answers a ball driven into it within the same event,
        // AirImpacts.h, and that impulse is the cloth's, not the pair's.)
        if (e.kind != EventKind::BallBall) continue;
        if (e.before[0].motion == MotionState::Airborne || e.before[1].motion == MotionState::Airborne) continue;
        const double scale = r.balls[static_cast<std::size_t>(e.balls[0])].mass * e.before[0].velocity.norm()
                             + r.balls[static_cast<std::size_t>(e.balls[1])].mass * e.before[1].velocity.norm();
        const double dp = testing::momentumChange(r, e);
        m.worstMomentumChange = std::max(m.worstMomentumChange, dp);
        if (dp > 1e-12 * scale + 1e-15)
            v.add(FailureKind::Momentum, "event " + std::to_string(k) + " (ball-ball at t = " + number(e.time) +
                                             ") changes the momentum by " + number(dp) + " N s");
    }
    double group = 0.0;
    const std::string why = testing::groupMomentumProblem(r, &group);
    m.worstMomentumChange = std::max(m.worstMomentumChange, group);
    if (!why.empty()) v.add(FailureKind::Momentum, why);
}

// The run ends with every ball at rest, and no timeline still moves after end_time.
void checkEnd(const SimulationResult& r, Verdict& v)
{
    if (r.status == SimulationStatus::EventLimit) v.add(FailureKind::EventLimit, r.error);
    if (r.status == SimulationStatus::ReachedUntil)
        v.add(FailureKind::NotAtRest, "stopped at its time limit, t = " + number(r.endTime) + ", with balls moving");
    if (r.status != SimulationStatus::AllAtRest) return;
    for (std::size_t i = 0; i < r.balls.size(); ++i) {
        const BallState end = r.stateAt(static_cast<int>(i), r.endTime);
        const BallState later = r.stateAt(static_cast<int>(i), r.endTime + 1.0);
        if (end.motion != MotionState::Stationary && !isOutOfPlay(end.motion))
            v.add(FailureKind::LostStop, "ball " + r.balls[i].id + " is " + std::string(toString(end.motion)) + " at end_time " +
                                             number(r.endTime) + " (" + number(end.velocity.norm()) + " m/s)");
        else if (later.position != end.position)
            v.add(FailureKind::LostStop, "ball " + r.balls[i].id + "'s timeline still moves after end_time " + number(r.endTime) +
                                             " (" + number((later.position - end.position).norm()) + " m in the next second)");
    }
}

bool sameBallState(const BallState& a, const BallState& b) { return testing::sameState(a, b); }

}  // namespace

std::string_view toString(FailureKind kind)
{
    switch (kind) {
    case FailureKind::EventLimit: return "event-limit";
    case FailureKind::NotAtRest: return "not-at-rest";
    case FailureKind::LostStop: return "lost-stop";
    case FailureKind::Overlap: return "overlap";
    case FailureKind::Escape: return "escape";
    case FailureKind::Energy: return "energy";
    case FailureKind::Momentum: return "momentum";
    case FailureKind::Timeline: return "timeline";
    case FailureKind::Determinism: return "determinism";
    }
    return "unknown";
}

std::span<const FailureKind> failureKinds() { return kKinds; }

bool sameRun(const SimulationResult& a, const SimulationResult& b)
{
    if (a.status != b.status || std::memcmp(&a.endTime, &b.endTime, sizeof(double)) != 0 || a.events.size() != b.events.size()
        || a.timelines.size() != b.timelines.size())
        return false;
    for (std::size_t k = 0; k < a.events.size(); ++k) {
        const Event& x = a.events[k];
        const Event& y = b.events[k];
        if (x.kind != y.kind || x.time != y.time || x.balls != y.balls || x.cushion != y.cushion || x.jaw != y.jaw
            || x.pocket != y.pocket || x.impulse != y.impulse || x.normal != y.normal || x.approachSpeed != y.approachSpeed
            || x.held != y.held || x.holdImpulse != y.holdImpulse || x.grouped != y.grouped)
            return false;
        for (std::size_t q = 0; q < 2; ++q)
            if (!sameBallState(x.before[q], y.before[q]) || !sameBallState(x.after[q], y.after[q])) return false;
        if (x.group.size() != y.group.size()) return false;
        for (std::size_t q = 0; q < x.group.size(); ++q)
            if (x.group[q].ball != y.group[q].ball || !sameBallState(x.group[q].before, y.group[q].before) ||
                !sameBallState(x.group[q].after, y.group[q].after))
                return false;
    }
    for (std::size_t i = 0; i < a.timelines.size(); ++i) {
        if (a.timelines[i].size() != b.timelines[i].size()) return false;
        for (std::size_t k = 0; k < a.timelines[i].size(); ++k) {
            const MotionSegment& x = a.timelines[i][k];
            const MotionSegment& y = b.timelines[i][k];
            if (x.start != y.start || x.push != y.push || !sameBallState(x.state, y.state)) return false;
        }
    }
    return true;
}

namespace {

struct Fnv {
    std::uint64_t h = 1469598103934665603ull;
    template <typename T>
    void add(const T& value)
    {
        unsigned char bytes[sizeof(T)];
        std::memcpy(bytes, &value, sizeof(T));
        for (unsigned char b : bytes) h = (h ^ b) * 1099511628211ull;
    }
    void add(const Vec2& v) { add(v.x()), add(v.y()); }
    void add(const Vec3& v) { add(v.x()), add(v.y()), add(v.z()); }
    void add(const BallState& s)
    {
        add(s.position), add(s.velocity), add(s.spin), add(static_cast<int>(s.motion)), add(s.pocket), add(s.z), add(s.vz);
    }
};

}  // namespace

std::uint64_t runDigest(const SimulationResult& r)
{
    Fnv f;
    f.add(static_cast<int>(r.status));
    f.add(r.endTime);
    for (const Event& e : r.events) {
        f.add(static_cast<int>(e.kind)), f.add(e.time), f.add(e.balls[0]), f.add(e.balls[1]);
        f.add(e.cushion), f.add(e.jaw), f.add(e.pocket), f.add(e.impulse), f.add(e.normal), f.add(e.approachSpeed);
        f.add(e.held), f.add(e.holdImpulse), f.add(e.grouped);
        for (std::size_t q = 0; q < 2; ++q) f.add(e.before[q]), f.add(e.after[q]);
        for (const Event::GroupChange& g : e.group) f.add(g.ball), f.add(g.before), f.add(g.after);
    }
    for (const auto& timeline : r.timelines)
        for (const MotionSegment& s : timeline) f.add(s.start), f.add(s.push), f.add(s.pushZ), f.add(s.state);
    return f.h;
}

std::vector<Failure> checkRun(const Setup& setup, const SimulationResult& result, const CheckOptions& options,
                              RunMeasures* measures, const SimulationOptions& simulation)
{
    Verdict v;
    RunMeasures m;
    checkEnd(result, v);
    checkStates(result, options, v, m);
    checkEvents(result, options, v, m);
    const std::string timeline = testing::timelineProblem(result);
    if (!timeline.empty()) v.add(FailureKind::Timeline, timeline);
    if (options.determinism && !sameRun(result, simulate(setup, simulation)))
        v.add(FailureKind::Determinism, "a second run of the same setup gave different events or timelines");
    if (measures) *measures = m;
    return v.take();
}

std::string describe(const std::vector<Failure>& failures)
{
    std::string out;
    for (const Failure& f : failures) out += std::string(toString(f.kind)) + ": " + f.message + "\n";
    return out;
}

}  // namespace cuelab::soak
