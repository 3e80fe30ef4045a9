#include "CuePlacement.h"

#include "CueStickMesh.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace cuelab {

namespace {

constexpr double kTipRadius = 0.0065, kButtRadius = 0.0145;  // m, as CueStickMesh
constexpr double kClearance = 0.002;                         // m kept between the stick and a ball
constexpr double kMaxElevationDeg = 85.0;

QVector3D q(const Vec3& v) { return QVector3D(static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())); }

}  // namespace

double cueStickRadius(double along) { return kTipRadius + (kButtRadius - kTipRadius) * along / kCueLength; }

bool cueClearsBalls(const std::vector<Ball>& balls, int struck, const Vec3& tip, const Vec3& along, double length)
{
    for (std::size_t j = 0; j < balls.size(); ++j) {
        if (static_cast<int>(j) == struck || balls[j].state.motion == MotionState::Pocketed) continue;
        const Vec3 c(balls[j].state.position.x(), balls[j].state.position.y(), balls[j].radius);
        const double s = std::clamp((c - tip).dot(along), 0.0, length);
        const double distance = (c - (tip + s * along)).norm();
        if (distance < balls[j].radius + cueStickRadius(s) + kClearance) return false;
    }
    return true;
}

Vec3 tipContactPoint(const Ball& ball, const CueStrike& shot)
{
    const double r = ball.radius;
    const double h = shot.headingDeg * std::numbers::pi / 180.0;
    const Vec3 d(std::cos(h), std::sin(h), 0.0);
    const Vec3 right(d.y(), -d.x(), 0.0);  // the player's right, looking along d
    const Vec3 up(0.0, 0.0, 1.0);
    const double a = std::clamp(shot.side, -0.9, 0.9) * r, b = std::clamp(shot.height, -0.9, 0.9) * r;
    const double depth = std::sqrt(std::max(0.0, r * r - a * a - b * b));
    const Vec3 centre(ball.state.position.x(), ball.state.position.y(), r);
    return Vec3(centre - depth * d + a * right + b * up);
}

std::optional<CuePose> cuePose(const SimulationResult& result, const std::vector<Ball>& balls, const CueStrike& shot)
{
    const int index = result.ballIndex(shot.ball);
    if (index < 0 || static_cast<std::size_t>(index) >= balls.size()) return std::nullopt;
    const Ball& ball = balls[static_cast<std::size_t>(index)];
    const double h = shot.headingDeg * std::numbers::pi / 180.0;
    const Vec3 d(std::cos(h), std::sin(h), 0.0);
    const Vec3 up(0.0, 0.0, 1.0);
    const Vec3 contact = tipContactPoint(ball, shot);

    auto along = [&d, &up](double elevationDeg) {
        const double e = elevationDeg * std::numbers::pi / 180.0;
        return Vec3(-std::cos(e) * d + std::sin(e) * up);  // tip -> butt
    };
    CuePose pose;
    pose.elevationDeg = std::clamp(shot.elevationDeg, 0.0, 90.0);
    pose.length = kCueLength;
    Vec3 axis = along(pose.elevationDeg);
    Vec3 tip = contact + 0.02 * axis;
    if (!cueClearsBalls(balls, index, tip, axis, kCueLength)) {
        bool cleared = false;
        for (double e = std::ceil(pose.elevationDeg) + 1.0; e <= kMaxElevationDeg; e += 1.0) {
            const Vec3 tryAxis = along(e);
            const Vec3 tryTip = contact + 0.02 * tryAxis;
            if (cueClearsBalls(balls, index, tryTip, tryAxis, kCueLength)) {
                pose.elevationDeg = e;
                axis = tryAxis;
                tip = tryTip;
                cleared = true;
                break;
            }
        }
        pose.raised = cleared;
        if (!cleared) {
            // Boxed in: the shot's elevation, shortened to what clears (at least the tip's first cm).
            double lo = 0.01, hi = kCueLength;
            for (int k = 0; k < 30; ++k) {
                const double mid = 0.5 * (lo + hi);
                (cueClearsBalls(balls, index, tip, axis, mid) ? lo : hi) = mid;
            }
            pose.length = lo;
        }
    }
    const Vec3 side = up.cross(axis).normalized();
    const Vec3 third = axis.cross(side);
    const auto scale = static_cast<float>(pose.length / kCueLength);
    pose.model.setColumn(0, QVector4D(scale * q(axis), 0.0f));
    pose.model.setColumn(1, QVector4D(q(side), 0.0f));
    pose.model.setColumn(2, QVector4D(q(third), 0.0f));
    pose.model.setColumn(3, QVector4D(q(tip), 1.0f));
    return pose;
}

}  // namespace cuelab
