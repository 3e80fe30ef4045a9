#pragma once
// Pieces shared by the event explainers (internal to core/explain).

#include "Explain.h"
#include "AirImpacts.h"
#include "Flight.h"
#include "Quartic.h"
#include "StepBuilder.h"

#include <array>
#include <optional>
#include <string>

namespace cuelab::explain::detail {

const std::string& ballName(const SimulationResult& r, int ball);
Body makeBody(const SimulationResult& r, int ball, const BallState& before, const BallState& after);

// "Motion up to the event": the closed-form state at the event from the segment's start.
void addMotionStep(std::vector<Step>& steps, const SimulationResult& r, int ball, const std::string& letter,
                   const SegmentBefore& seg, double t);
// The same for a flying ball: its parabola in space (Flight.h), free or held against a ball.
void addFlightStep(std::vector<Step>& steps, const SimulationResult& r, int ball, const std::string& letter,
                   const SegmentBefore& seg, double t);
// Energy (translation, rotation) and momentum of the bodies before and after.
void addEnergyStep(Explanation& e, const Text& where);
void addMomentumStep(Explanation& e, const Text& law);

// Time of impact of the event (collisions and pockets), from the simulator's gap polynomials and
// detection functions over the bodies' present closed-form paths.
TimeOfImpact timeOfImpact(const SimulationResult& r, int index);
void addToiStep(Explanation& e, const Text& law);

// A flying ball's collisions (AirToi.cpp, AirBallBallExplain.cpp): the centre's path in space over
// its segment, the time of impact in space, the roots of a gap polynomial listed with the chosen one
// (`late`: the event's τ; `chosen` kNever when the detection from t0 does not find it), and the
// momentum in space with the cloth's impulse `cloth` (the only outside impulse in an instant).
SpacePath spacePathOf(const SimulationResult& r, int ball, const SegmentBefore& seg);
void chooseRoots(TimeOfImpact& toi, const Quartic& q, double chosen, double late, bool& touchingNow);
TimeOfImpact airBallBallToi(const SimulationResult& r, int index);
// The sentence for an event whose states after agree with its law's to rounding only.
Text roundedNormal();
void explainAirBallBall(const SimulationResult& r, int index, Explanation& e);
// A flying ball held on a ball on the cloth (AirHoldExplain.cpp): the re-seat and the contact force's
// steps from `states` (the event's order: its states before for a touch with no approach, `resting`,
// else the law's result), and the states the hold goes on from; none when the simulator's
// computation does not hold the pair.
std::optional<std::array<BallState, 2>> addAirHoldSteps(Explanation& e, const std::array<BallState, 2>& states, bool resting,
                                                        const Ball& A, const Ball& B, const PhysicsParams& p);
void explainAirCushion(const SimulationResult& r, int index, Explanation& e);  // AirCushionExplain.cpp
void addSpaceMomentumStep(Explanation& e, const Text& law, const std::string& key, const std::string& symbol, const Vec3& outside);

void explainCueStrike(const SimulationResult& r, int index, const std::optional<CueStrike>& shot, Explanation& e);
void explainBallBall(const SimulationResult& r, int index, Explanation& e);
void explainCushion(const SimulationResult& r, int index, Explanation& e);
void explainPocket(const SimulationResult& r, int index, Explanation& e);
void explainBallTable(const SimulationResult& r, int index, Explanation& e);  // FlightExplain.cpp
void explainOffTable(const SimulationResult& r, int index, Explanation& e);
void explainTransition(const SimulationResult& r, int index, Explanation& e);

}  // namespace cuelab::explain::detail
