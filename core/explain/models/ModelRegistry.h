#pragma once
// Explainers of the collision models, one file each under core/explain/models/, listed once in
// ModelRegistry.cpp (the only line a new model adds outside its own file).
//
// An explainer resolves the collision with the model's own resolver (asking it for its trace of
// intermediate numbers) and appends the model's steps: the law, its inputs and results. It returns
// what the model alone gives; the caller compares that with the event (the simulator may add the
// separation floor of Detection.h afterwards) and adds geometry, energy and momentum around it.

#include "BallBallCollision.h"
#include "CushionCollision.h"
#include "Explanation.h"
#include "Parameters.h"

#include <string>
#include <vector>

namespace cuelab::explain {

struct BallBallInput {
    BallBallBody a, b;      // the states just before, radius, mass (a = the event's first ball)
    PhysicsParams params;
    std::string nameA, nameB;  // the balls' ids, for the words
};
using BallBallExplainer = BallBallResult (*)(const BallBallInput& in, std::vector<Step>& steps);

struct CushionInput {
    BallState before;
    Vec2 normal = Vec2::Zero();  // unit, from the cushion (or jaw tip) towards the ball's centre
    double radius = 0.0, mass = 0.0;
    double noseHeight = 0.0;     // m, height of the cushion's contact line above the cloth
    PhysicsParams params;
    std::string name;            // the ball's id
    bool jaw = false;            // a circular jaw tip rather than a straight cushion
};
using CushionExplainer = CushionResult (*)(const CushionInput& in, std::vector<Step>& steps);

// The explainer registered for a model, or nullptr (then explain() shows the model's result alone).
BallBallExplainer ballBallExplainer(BallBallModel model);
CushionExplainer cushionExplainer(BallCushionModel model);

// Every model's explainer, declared here and defined in its own file.
BallBallResult explainFrictionless(const BallBallInput& in, std::vector<Step>& steps);
BallBallResult explainFrictional(const BallBallInput& in, std::vector<Step>& steps);
CushionResult explainMirror(const CushionInput& in, std::vector<Step>& steps);
CushionResult explainHan2005(const CushionInput& in, std::vector<Step>& steps);
CushionResult explainMathavan2010(const CushionInput& in, std::vector<Step>& steps);
CushionResult explainStronge(const CushionInput& in, std::vector<Step>& steps);

}  // namespace cuelab::explain
