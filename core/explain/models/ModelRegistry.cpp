// The registration point of the collision models' explainers: one line per model.
#include "ModelRegistry.h"

#include <utility>

namespace cuelab::explain {

namespace {

constexpr std::pair<BallBallModel, BallBallExplainer> kBallBall[] = {
    {BallBallModel::Frictionless, explainFrictionless},
    {BallBallModel::Frictional, explainFrictional},
};

constexpr std::pair<BallCushionModel, CushionExplainer> kCushion[] = {
    {BallCushionModel::Mirror, explainMirror},
    {BallCushionModel::Han2005, explainHan2005},
    {BallCushionModel::Mathavan2010, explainMathavan2010},
    {BallCushionModel::Stronge, explainStronge},
};

}  // namespace

BallBallExplainer ballBallExplainer(BallBallModel model)
{
    for (const auto& [m, f] : kBallBall)
        if (m == model) return f;
    return nullptr;
}

CushionExplainer cushionExplainer(BallCushionModel model)
{
    for (const auto& [m, f] : kCushion)
        if (m == model) return f;
    return nullptr;
}

}  // namespace cuelab::explain
