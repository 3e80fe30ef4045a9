#include "Curves.h"

#include "Event.h"
#include "Flight.h"
#include "Motion.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace cuelab::plots {

std::string_view label(Quantity q)
{
    switch (q) {
    case Quantity::Speed: return "speed";
    case Quantity::SlipSpeed: return "slip speed";
    case Quantity::SpinX: return "spin wx";
    case Quantity::SpinY: return "spin wy";
    case Quantity::SpinZ: return "spin wz";
    case Quantity::TranslationalEnergy: return "translational energy";
    case Quantity::RotationalEnergy: return "rotational energy";
    case Quantity::KineticEnergy: return "kinetic energy";
    case Quantity::Momentum: return "momentum";
    case Quantity::MomentumX: return "momentum px";
    case Quantity::MomentumY: return "momentum py";
    case Quantity::EnergyLostToEvents: return "energy lost to events";
    case Quantity::EnergyLostToCloth: return "energy lost to the cloth";
    case Quantity::Height: return "height z";
    case Quantity::VerticalSpeed: return "vertical speed vz";
    }
    return "speed";
}

std::string_view unit(Quantity q)
{
    switch (q) {
    case Quantity::Speed:
    case Quantity::SlipSpeed:
    case Quantity::VerticalSpeed: return "m/s";
    case Quantity::Height: return "m";
    case Quantity::SpinX:
    case Quantity::SpinY:
    case Quantity::SpinZ: return "rad/s";
    case Quantity::Momentum:
    case Quantity::MomentumX:
    case Quantity::MomentumY: return "N s";
    default: return "J";
    }
}

bool isEnergy(Quantity q)
{
    return q == Quantity::TranslationalEnergy || q == Quantity::RotationalEnergy || q == Quantity::KineticEnergy ||
           q == Quantity::EnergyLostToEvents || q == Quantity::EnergyLostToCloth;
}

double valueOf(Quantity q, const BallState& s, double radius, double mass)
{
    if (isOutOfPlay(s.motion)) return 0.0;
    switch (q) {
    case Quantity::Speed: return s.velocity.norm();
    case Quantity::SlipSpeed: return slipVelocity(s, radius).norm();
    case Quantity::SpinX: return s.spin.x();
    case Quantity::SpinY: return s.spin.y();
    case Quantity::SpinZ: return s.spin.z();
    case Quantity::TranslationalEnergy: return translationalEnergy(s, mass);  // (with vz in flight)
    case Quantity::RotationalEnergy: return 0.5 * ballInertia(mass, radius) * s.spin.squaredNorm();
    case Quantity::KineticEnergy: return kineticEnergy(s, radius, mass);
    case Quantity::Momentum: return mass * s.velocity.norm();
    case Quantity::MomentumX: return mass * s.velocity.x();
    case Quantity::MomentumY: return mass * s.velocity.y();
    case Quantity::EnergyLostToEvents:
    case Quantity::EnergyLostToCloth: return 0.0;  // the table's only (tableCurve)
    case Quantity::Height: return s.z;
    case Quantity::VerticalSpeed: return s.vz;
    }
    return 0.0;
}

BallState stateJustBefore(const SimulationResult& result, int index, double t)
{
    const std::vector<MotionSegment>& timeline = result.timelines.at(static_cast<std::size_t>(index));
    const double R = result.balls.at(static_cast<std::size_t>(index)).radius;
    // The last segment that starts strictly before t (SimulationResult::stateAt takes the last one
    // starting at or before t), then its transitions up to, but not at, t.
    auto it = std::lower_bound(timeline.begin(), timeline.end(), t,
                               [](const MotionSegment& s, double time) { return s.start < time; });
    if (it != timeline.begin()) --it;
    // A held push, or a summed series of bounces (whose stored state is its landing, not its course).
    if (it->pushed() || it->bounces) return segmentState(*it, R, result.physics, t - it->start);
    BallState s = it->state;
    double start = it->start;
    for (;;) {
        const Transition tr = nextTransition(s, R, result.physics);
        if (tr.after == kNever || start + tr.after >= t) break;
        s = applyTransition(s, R, result.physics);
        start += tr.after;
    }
    return evolve(s, R, result.physics, t - start);
}

std::vector<double> sampleTimes(double a, double b, const SamplingOptions& options, double end)
{
    const double maxStep = options.maxStep > 0.0 ? options.maxStep : std::max(end, 1e-3) / 600.0;
    // Chebyshev-Lobatto nodes: the widest gap, in the middle, is about (b - a) pi / (2 (n - 1)).
    const double needed = std::ceil(std::numbers::pi / 2.0 * (b - a) / maxStep) + 1.0;
    const int n = std::max(std::max(options.samplesPerPiece, 2), static_cast<int>(std::min(needed, 1e6)));
    std::vector<double> times;
    times.reserve(static_cast<std::size_t>(n));
    times.push_back(a);
    for (int k = 1; k < n - 1; ++k) {
        const double t = a + (b - a) * 0.5 * (1.0 - std::cos(std::numbers::pi * k / (n - 1)));
        if (t > times.back() && t < b) times.push_back(t);
    }
    if (b > times.back()) times.push_back(b);
    return times;
}

namespace {

double endOf(const SimulationResult& result, const SamplingOptions& options)
{
    return options.until >= 0.0 ? options.until : result.endTime;
}

bool involves(const Event& e, int ball)
{
    return e.balls[0] == ball || (e.kind == EventKind::BallBall && e.balls[1] == ball);
}

// The boundaries of the pieces: 0, the selected event times in (0, end), and end; `isEvent` says
// which boundaries are event times (whose left limit differs from stateAt).
struct Breaks {
    std::vector<double> times;
    std::vector<bool> isEvent;
};

template <typename Selected>
Breaks breaksOf(const SimulationResult& result, double end, Selected selected)
{
    Breaks b;
    b.times.push_back(0.0);
    b.isEvent.push_back(false);
    for (const Event& e : result.events) {
        if (!selected(e) || e.time > end) continue;
        if (e.time <= b.times.back()) {
            if (e.time == b.times.back()) b.isEvent.back() = true;
            continue;
        }
        b.times.push_back(e.time);
        b.isEvent.push_back(true);
    }
    if (end > b.times.back()) {
        b.times.push_back(end);
        b.isEvent.push_back(false);
    }
    return b;
}

}  // namespace

std::vector<Piece> sampleBall(const SimulationResult& result, int index, const SamplingOptions& options)
{
    const double end = endOf(result, options);
    const Breaks breaks = breaksOf(result, end, [index](const Event& e) { return involves(e, index); });
    std::vector<Piece> pieces;
    for (std::size_t k = 0; k + 1 < breaks.times.size(); ++k) {
        const double a = breaks.times[k];
        const double b = breaks.times[k + 1];
        if (isOutOfPlay(result.stateAt(index, a).motion)) break;
        Piece piece;
        const std::vector<double> times = sampleTimes(a, b, options, end);
        for (std::size_t i = 0; i < times.size(); ++i) {
            const bool closing = i + 1 == times.size() && breaks.isEvent[k + 1];
            piece.samples.push_back({times[i], closing ? stateJustBefore(result, index, times[i])
                                                       : result.stateAt(index, times[i])});
        }
        pieces.push_back(std::move(piece));
    }
    return pieces;
}

std::vector<TablePiece> sampleTable(const SimulationResult& result, const SamplingOptions& options)
{
    const double end = endOf(result, options);
    const Breaks breaks = breaksOf(result, end, [](const Event&) { return true; });
    const int balls = static_cast<int>(result.balls.size());
    std::vector<TablePiece> pieces;
    for (std::size_t k = 0; k + 1 < breaks.times.size(); ++k) {
        TablePiece piece;
        piece.times = sampleTimes(breaks.times[k], breaks.times[k + 1], options, end);
        for (std::size_t i = 0; i < piece.times.size(); ++i) {
            const double t = piece.times[i];
            const bool closing = i + 1 == piece.times.size() && breaks.isEvent[k + 1];
            std::vector<BallState> states;
            states.reserve(static_cast<std::size_t>(balls));
            for (int b = 0; b < balls; ++b)
                states.push_back(closing ? stateJustBefore(result, b, t) : result.stateAt(b, t));
            piece.states.push_back(std::move(states));
        }
        pieces.push_back(std::move(piece));
    }
    return pieces;
}

double energyPutIn(const SimulationResult& result, double t)
{
    // (The setup's balls' mechanical energy: a ball given a height brings m g z as well.)
    double sum = 0.0;
    for (const Ball& b : result.balls) sum += mechanicalEnergy(b.state, b.radius, b.mass, result.physics.gravity);
    for (const Event& e : result.events) {
        if (e.time > t) break;
        if (e.kind != EventKind::CueStrike) continue;
        const Ball& b = result.balls.at(static_cast<std::size_t>(e.balls[0]));
        sum += kineticEnergy(e.after[0], b.radius, b.mass) - kineticEnergy(e.before[0], b.radius, b.mass);
    }
    return sum;
}

double energyLostToEvents(const SimulationResult& result, double t)
{
    double sum = 0.0;
    for (const Event& e : result.events) {
        if (e.time > t) break;
        if (e.kind == EventKind::CueStrike) continue;
        for (std::size_t k = 0; k < 2 && e.balls[k] >= 0; ++k) {
            const Ball& b = result.balls.at(static_cast<std::size_t>(e.balls[k]));
            // (An event keeps the height but for a ball leaving play: its m g z leaves with it.)
            const double g = result.physics.gravity;
            sum += mechanicalEnergy(e.before[k], b.radius, b.mass, g) - mechanicalEnergy(e.after[k], b.radius, b.mass, g);
        }
    }
    return sum;
}

double totalOf(Quantity q, const SimulationResult& result, const std::vector<BallState>& states)
{
    if (q == Quantity::Momentum) {
        Vec2 p = Vec2::Zero();
        for (std::size_t b = 0; b < states.size(); ++b)
            if (!isOutOfPlay(states[b].motion)) p += result.balls[b].mass * states[b].velocity;
        return p.norm();
    }
    double sum = 0.0;
    for (std::size_t b = 0; b < states.size(); ++b)
        sum += valueOf(q, states[b], result.balls[b].radius, result.balls[b].mass);
    return sum;
}

namespace {

// Appends a piece to the curve: joined to the last polyline when it starts where that one ended
// (same time, same value up to rounding), else as a new polyline.
void append(std::vector<Polyline>& curve, Polyline piece)
{
    if (!curve.empty() && !piece.times.empty()) {
        Polyline& last = curve.back();
        const double a = last.values.back();
        const double b = piece.values.front();
        const bool sameTime = last.times.back() == piece.times.front();
        if (sameTime && std::abs(a - b) <= 1e-9 * std::max({std::abs(a), std::abs(b), 1e-9})) {
            last.times.insert(last.times.end(), piece.times.begin() + 1, piece.times.end());
            last.values.insert(last.values.end(), piece.values.begin() + 1, piece.values.end());
            return;
        }
    }
    if (piece.times.size() >= 2) curve.push_back(std::move(piece));
}

}  // namespace

std::vector<Polyline> ballCurve(const SimulationResult& result, int index, Quantity q, const SamplingOptions& options)
{
    const double R = result.balls.at(static_cast<std::size_t>(index)).radius;
    const double m = result.balls.at(static_cast<std::size_t>(index)).mass;
    std::vector<Polyline> curve;
    for (const Piece& piece : sampleBall(result, index, options)) {
        Polyline line;
        for (const Sample& s : piece.samples) {
            line.times.push_back(s.time);
            line.values.push_back(valueOf(q, s.state, R, m));
        }
        append(curve, std::move(line));
    }
    return curve;
}

namespace {

// The table's kinetic energy plus the potential energy m g z of balls in flight, J.
double mechanicalTotal(const SimulationResult& result, const std::vector<BallState>& states)
{
    double sum = 0.0;
    for (std::size_t i = 0; i < states.size() && i < result.balls.size(); ++i)
        sum += mechanicalEnergy(states[i], result.balls[i].radius, result.balls[i].mass, result.physics.gravity);
    return sum;
}

}  // namespace

std::vector<Polyline> tableCurve(const SimulationResult& result, Quantity q, const SamplingOptions& options)
{
    std::vector<Polyline> curve;
    for (const TablePiece& piece : sampleTable(result, options)) {
        Polyline line;
        line.times = piece.times;
        if (q == Quantity::EnergyLostToEvents || q == Quantity::EnergyLostToCloth) {
            // Inside a piece no event happens: the events' share and the energy put in are those
            // of the events at or before its start.
            const double start = piece.times.empty() ? 0.0 : piece.times.front();
            const double events = energyLostToEvents(result, start), in = energyPutIn(result, start);
            for (const std::vector<BallState>& states : piece.states)
                line.values.push_back(q == Quantity::EnergyLostToEvents
                                          ? events
                                          : in - mechanicalTotal(result, states) - events);
        } else {
            for (const std::vector<BallState>& states : piece.states) line.values.push_back(totalOf(q, result, states));
        }
        append(curve, std::move(line));
    }
    return curve;
}

}  // namespace cuelab::plots
