// Names of the enums as they appear in files, the command line and the UI (CONTRACT.md).

#include "Ball.h"
#include "Event.h"
#include "Parameters.h"
#include "resolve/CushionModel.h"

#include <cmath>

namespace cuelab {

std::string_view toString(MotionState s)
{
    switch (s) {
    case MotionState::Stationary: return "stationary";
    case MotionState::Spinning: return "spinning";
    case MotionState::Sliding: return "sliding";
    case MotionState::Rolling: return "rolling";
    case MotionState::Pocketed: return "pocketed";
    case MotionState::Airborne: return "airborne";
    case MotionState::OffTable: return "off-table";
    }
    return "stationary";
}

bool parseMotionState(std::string_view text, MotionState& out)
{
    for (MotionState s : {MotionState::Stationary, MotionState::Spinning, MotionState::Sliding,
                          MotionState::Rolling, MotionState::Pocketed, MotionState::Airborne, MotionState::OffTable}) {
        if (toString(s) == text) {
            out = s;
            return true;
        }
    }
    return false;
}

std::string_view toString(BallBallModel m)
{
    return m == BallBallModel::Frictional ? "frictional" : "frictionless";
}

std::string_view toString(BallCushionModel m) { return cushionModel(m).name; }

std::string_view toString(EventKind k)
{
    switch (k) {
    case EventKind::CueStrike: return "cue-strike";
    case EventKind::BallBall: return "ball-ball";
    case EventKind::BallCushion: return "ball-cushion";
    case EventKind::BallJaw: return "ball-cushion";
    case EventKind::BallPocket: return "ball-pocket";
    case EventKind::SlideToRoll: return "slide-to-roll";
    case EventKind::SlideToSpin: return "slide-to-spin";
    case EventKind::SlideToStop: return "slide-to-stop";
    case EventKind::RollToSpin: return "roll-to-spin";
    case EventKind::RollToStop: return "roll-to-stop";
    case EventKind::SpinToStop: return "spin-to-stop";
    case EventKind::BallTable: return "ball-table";
    case EventKind::BallOffTable: return "ball-off-table";
    }
    return "cue-strike";
}

bool isTransition(EventKind k)
{
    switch (k) {
    case EventKind::SlideToRoll:
    case EventKind::SlideToSpin:
    case EventKind::SlideToStop:
    case EventKind::RollToSpin:
    case EventKind::RollToStop:
    case EventKind::SpinToStop: return true;
    default: return false;
    }
}

bool isCollision(EventKind k)
{
    return k == EventKind::BallBall || k == EventKind::BallCushion || k == EventKind::BallJaw;
}

MotionState classify(const BallState& s, double radius)
{
    if (isOutOfPlay(s.motion)) return s.motion;
    if (s.z > kHeightTolerance || s.vz > 0.0) return MotionState::Airborne;
    const bool moving = s.velocity.norm() > kSpeedEpsilon;
    const bool slipping = slipVelocity(s, radius).norm() > kSpeedEpsilon;
    if (slipping) return MotionState::Sliding;
    if (moving) return MotionState::Rolling;
    if (std::abs(s.spin.z()) > kSpinEpsilon) return MotionState::Spinning;
    return MotionState::Stationary;
}

}  // namespace cuelab
