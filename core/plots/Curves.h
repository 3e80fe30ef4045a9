#pragma once
// Curves against time for the Plots dock and the printed report: speed, slip speed, spin components
// and kinetic energy of a ball, sampled from the exact closed-form motion.
//
// A curve is a list of pieces, one per stretch between two consecutive events of the ball (its
// collisions, its pocketing, its changes of motion) or, for the whole table, between any two events.
// A piece is never drawn across an event: its first sample is the state just after the event that
// opens it (SimulationResult::stateAt at that time) and its last the state just before the event
// that closes it (stateJustBefore). Inside, samples are SimulationResult::stateAt at their times,
// spaced like Chebyshev nodes (dense near both events, where the motion changes fastest) and never
// further apart than SamplingOptions::maxStep.

#include "Ball.h"
#include "Simulation.h"

#include <cstdint>
#include <string_view>
#include <vector>

namespace cuelab::plots {

enum class Quantity : std::uint8_t {
    Speed,                // |v|, m/s
    SlipSpeed,            // |u| = |v + R (z x w)| at the cloth contact, m/s
    SpinX,                // wx, rad/s
    SpinY,                // wy, rad/s
    SpinZ,                // wz (side spin), rad/s
    TranslationalEnergy,  // m |v|^2 / 2, J
    RotationalEnergy,     // I |w|^2 / 2, J
    KineticEnergy,        // the sum, J
    Momentum,             // |p| = m |v|, N s; the table's total is |Σ p|, not Σ |p|
    MomentumX,            // p_x, N s
    MomentumY,            // p_y, N s
    // The table only (tableCurve; 0 for a single ball): the kinetic energy the events took so far (a
    // collision's restitution and friction, a ball falling into a pocket), and what the cloth took so
    // far (the energy put in by the setup and the cue strike, minus what is left, minus the events'
    // share). Translation + rotation + the two losses = the energy put in, at every time; a ball in
    // flight also holds the potential energy m g z (counted in these sums, not drawn as a part).
    EnergyLostToEvents,   // J
    EnergyLostToCloth,    // J
    Height,               // z, the centre's height above its resting height, m (0 on the cloth)
    VerticalSpeed,        // vz, m/s, + up
};
inline constexpr Quantity kQuantities[] = {Quantity::Speed, Quantity::SlipSpeed, Quantity::SpinX,
                                           Quantity::SpinY, Quantity::SpinZ, Quantity::TranslationalEnergy,
                                           Quantity::RotationalEnergy, Quantity::KineticEnergy,
                                           Quantity::Momentum, Quantity::MomentumX, Quantity::MomentumY,
                                           Quantity::EnergyLostToEvents, Quantity::EnergyLostToCloth,
                                           Quantity::Height, Quantity::VerticalSpeed};

std::string_view label(Quantity q);  // "speed", "slip speed", "spin wx", ... "kinetic energy"
std::string_view unit(Quantity q);   // "m/s", "rad/s", "J", "m"
bool isEnergy(Quantity q);

// The quantity of one ball's state; a pocketed ball has none (0).
double valueOf(Quantity q, const BallState& s, double radius, double mass);

// The state of ball `index` just before time t: the left limit of the closed-form motion, so that at
// an event time it is the state before the event (stateAt gives the state after it).
BallState stateJustBefore(const SimulationResult& result, int index, double t);

struct Sample {
    double time = 0.0;  // s
    BallState state;
};
struct Piece {
    std::vector<Sample> samples;  // in time order; at least two, first and last at the piece's ends
};

struct SamplingOptions {
    int samplesPerPiece = 24;   // at least this many samples in every piece
    double maxStep = 0.0;       // s, largest gap between samples; <= 0: (end - 0) / 600
    double until = -1.0;        // s, end of the curves; < 0: the result's endTime
};

// The pieces of ball `index` from 0 to the end: broken at every event the ball takes part in (as an
// agent of a collision, a pocketing or a change of motion). A pocketed ball's curve ends at its
// pocketing. Pieces of zero length (simultaneous events) are left out.
std::vector<Piece> sampleBall(const SimulationResult& result, int index, const SamplingOptions& options = {});

// The whole table: broken at every event. Each sample holds the states of all balls at its time
// (just before the event at a piece's end).
struct TablePiece {
    std::vector<double> times;                    // s
    std::vector<std::vector<BallState>> states;   // per sample, per ball
};
std::vector<TablePiece> sampleTable(const SimulationResult& result, const SamplingOptions& options = {});

// The energy put into the table up to time t (J): the balls' energy as set up plus what each cue
// strike at or before t gave its ball.
double energyPutIn(const SimulationResult& result, double t);
// The kinetic energy the events at or before t took (J): Σ over them of the energy of their balls just
// before minus just after (the cue strike excluded: it gives).
double energyLostToEvents(const SimulationResult& result, double t);

// The sum over the balls of a quantity at one sample of the table (energies mainly); for Momentum the
// length of the summed momentum.
double totalOf(Quantity q, const SimulationResult& result, const std::vector<BallState>& states);

// A curve ready to draw: polylines of (time, value). Consecutive pieces are joined where the value
// is continuous across the event between them (a change of motion leaves the speed as it was), and
// broken where it jumps (a collision), so that no line is ever drawn across a jump.
struct Polyline {
    std::vector<double> times;   // s
    std::vector<double> values;  // in unit(q)
};
std::vector<Polyline> ballCurve(const SimulationResult& result, int index, Quantity q,
                                const SamplingOptions& options = {});
std::vector<Polyline> tableCurve(const SimulationResult& result, Quantity q, const SamplingOptions& options = {});

// The times at which a piece from a to b is sampled (both ends included).
std::vector<double> sampleTimes(double a, double b, const SamplingOptions& options, double end);

}  // namespace cuelab::plots
