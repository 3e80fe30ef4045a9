#pragma once
// Pieces shared by the event explainers (internal to core/explain).

#include "Explain.h"
#include "StepBuilder.h"

#include <string>

namespace cuelab::explain::detail {

const std::string& ballName(const SimulationResult& r, int ball);
Body makeBody(const SimulationResult& r, int ball, const BallState& before, const BallState& after);

// "Motion up to the event": the closed-form state at the event from the segment's start.
void addMotionStep(std::vector<Step>& steps, const SimulationResult& r, int ball, const std::string& letter,
                   const SegmentBefore& seg, double t);
// Energy (translation, rotation) and momentum of the bodies before and after.
void addEnergyStep(Explanation& e, const Text& where);
void addMomentumStep(Explanation& e, const Text& law);

// Time of impact of the event (collisions and pockets), from the simulator's gap polynomials and
// detection functions over the bodies' present closed-form paths.
TimeOfImpact timeOfImpact(const SimulationResult& r, int index);
void addToiStep(Explanation& e, const Text& law);

void explainCueStrike(const SimulationResult& r, int index, const std::optional<CueStrike>& shot, Explanation& e);
void explainBallBall(const SimulationResult& r, int index, Explanation& e);
void explainCushion(const SimulationResult& r, int index, Explanation& e);
void explainPocket(const SimulationResult& r, int index, Explanation& e);
void explainBallTable(const SimulationResult& r, int index, Explanation& e);  // FlightExplain.cpp
void explainOffTable(const SimulationResult& r, int index, Explanation& e);
void explainTransition(const SimulationResult& r, int index, Explanation& e);

}  // namespace cuelab::explain::detail
