#include "OrbitCamera.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace cuelab {

namespace {

constexpr float kDegPerRad = 180.0f / std::numbers::pi_v<float>;
const QVector3D kWorldUp(0.0f, 0.0f, 1.0f);

float radians(float degrees) { return degrees / kDegPerRad; }

// The rotation of a camera whose right axis is `right` (horizontal) and whose line of sight points
// `elevationDeg` below the horizontal.
QQuaternion rotationFrom(const QVector3D& right, float elevationDeg)
{
    const float e = radians(elevationDeg);
    // Horizontal direction from the target towards the eye: behind the camera.
    const QVector3D behind = QVector3D::crossProduct(right, kWorldUp);
    const QVector3D back = std::cos(e) * behind + std::sin(e) * kWorldUp;
    const QVector3D up = QVector3D::crossProduct(back, right);
    return QQuaternion::fromAxes(right, up, back).normalized();
}

// Rotation of a camera standing `elevationDeg` above the horizontal looking along `headingDeg`.
QQuaternion rotationLookingAlong(float headingDeg, float elevationDeg)
{
    const float h = radians(headingDeg);
    return rotationFrom(QVector3D(std::sin(h), -std::cos(h), 0.0f), elevationDeg);
}

// Backs the camera off until every corner of `extent` (on the cloth and at rail height) lies inside
// the image with a small margin: perspective makes the near side of an oblique view the widest.
float fittingDistance(CameraPose pose, const QRectF& extent, float aspect)
{
    OrbitCamera probe;
    for (int i = 0; i < 200; ++i) {
        probe.setPose(pose);
        bool inside = true;
        for (const QPointF& c : {extent.topLeft(), extent.topRight(), extent.bottomLeft(), extent.bottomRight()}) {
            for (float z : {0.0f, 0.05f}) {
                const std::optional<QPointF> p =
                    probe.project(QVector3D(static_cast<float>(c.x()), static_cast<float>(c.y()), z), aspect);
                inside = inside && p && std::abs(p->x()) <= 0.97 && std::abs(p->y()) <= 0.97;
            }
        }
        if (inside) break;
        pose.distance *= 1.02f;
    }
    return pose.distance;
}

float smoothstep(float x)
{
    const float c = std::clamp(x, 0.0f, 1.0f);
    return c * c * (3.0f - 2.0f * c);
}

}  // namespace

// Re-orthonormalises the rotation with a horizontal right axis and a line of sight between the
// elevation limits. Float rounding in repeated quaternion products leaves a tiny roll; projecting the
// right axis back onto the horizontal removes it every time, so it cannot accumulate.
CameraPose OrbitCamera::constrained(CameraPose pose)
{
    const QQuaternion q = pose.rotation.normalized();
    const QVector3D back = q.rotatedVector(QVector3D(0.0f, 0.0f, 1.0f));
    QVector3D right = q.rotatedVector(QVector3D(1.0f, 0.0f, 0.0f));
    right.setZ(0.0f);
    if (right.lengthSquared() < 1e-8f) {
        // Rolled by a right angle: take the horizontal axis perpendicular to the line of sight.
        right = QVector3D(-back.y(), back.x(), 0.0f);
        if (right.lengthSquared() < 1e-8f) right = QVector3D(1.0f, 0.0f, 0.0f);
    }
    right.normalize();
    // atan2 rather than asin: asin loses half the digits near the vertical.
    const float horizontal = std::sqrt(back.x() * back.x() + back.y() * back.y());
    const float elevation = std::clamp(std::atan2(back.z(), horizontal) * kDegPerRad, kMinElevationDeg, kMaxElevationDeg);
    pose.rotation = rotationFrom(right, elevation);
    pose.distance = std::clamp(pose.distance, kMinDistance, kMaxDistance);
    return pose;
}

void OrbitCamera::setPose(const CameraPose& pose)
{
    transition_.reset();
    pose_ = constrained(pose);
}

QVector3D OrbitCamera::eye() const
{
    return pose_.target + pose_.distance * pose_.rotation.rotatedVector(QVector3D(0.0f, 0.0f, 1.0f));
}

QVector3D OrbitCamera::right() const { return pose_.rotation.rotatedVector(QVector3D(1.0f, 0.0f, 0.0f)); }
QVector3D OrbitCamera::up() const { return pose_.rotation.rotatedVector(QVector3D(0.0f, 1.0f, 0.0f)); }
QVector3D OrbitCamera::forward() const { return pose_.rotation.rotatedVector(QVector3D(0.0f, 0.0f, -1.0f)); }

float OrbitCamera::elevationDeg() const
{
    const QVector3D f = forward();
    return std::atan2(-f.z(), std::sqrt(f.x() * f.x() + f.y() * f.y())) * kDegPerRad;
}

void OrbitCamera::orbit(float yawDeg, float pitchDeg)
{
    transition_.reset();
    QQuaternion q = QQuaternion::fromAxisAndAngle(kWorldUp, yawDeg) * pose_.rotation;
    // A positive angle about the right axis lowers the eye; clamp the pitch to the elevation limits
    // before applying it, so the quaternion never leaves the allowed set.
    const float current = elevationDeg();
    const float wanted = std::clamp(current + pitchDeg, kMinElevationDeg, kMaxElevationDeg);
    const QVector3D axis = q.rotatedVector(QVector3D(1.0f, 0.0f, 0.0f));
    q = QQuaternion::fromAxisAndAngle(axis, current - wanted) * q;
    pose_.rotation = q;
    pose_ = constrained(pose_);
}

void OrbitCamera::pan(QPointF fromNdc, QPointF toNdc, float aspect)
{
    transition_.reset();
    const float planeZ = pose_.target.z();
    const Ray a = ray(fromNdc, aspect);
    const Ray b = ray(toNdc, aspect);
    if (std::abs(a.direction.z()) > 0.05f && std::abs(b.direction.z()) > 0.05f) {
        const QVector3D pa = a.origin + ((planeZ - a.origin.z()) / a.direction.z()) * a.direction;
        const QVector3D pb = b.origin + ((planeZ - b.origin.z()) / b.direction.z()) * b.direction;
        // Translating the camera by pa - pb moves the ray through toNdc onto pa.
        if ((pa - eye()).length() < 10.0f * kMaxDistance && (pb - eye()).length() < 10.0f * kMaxDistance) {
            pose_.target += pa - pb;
            return;
        }
    }
    // Edge-on: move in the plane through the target facing the camera.
    const float halfHeight = pose_.distance * std::tan(radians(kFieldOfViewDeg) / 2.0f);
    const QPointF d = fromNdc - toNdc;
    pose_.target += static_cast<float>(d.x()) * halfHeight * aspect * right() +
                    static_cast<float>(d.y()) * halfHeight * up();
}

void OrbitCamera::zoomTowards(const QVector3D& point, float factor)
{
    transition_.reset();
    const float newDistance = std::clamp(pose_.distance * factor, kMinDistance, kMaxDistance);
    const float f = newDistance / pose_.distance;
    // A homothety about `point` with a fixed orientation maps the eye's rays through `point` onto
    // themselves, so `point` stays where it is in the image.
    pose_.target = point + f * (pose_.target - point);
    pose_.distance = newDistance;
}

void OrbitCamera::centreOn(const QVector3D& point)
{
    transition_.reset();
    pose_.target = point;
}

QMatrix4x4 OrbitCamera::viewMatrix() const
{
    QMatrix4x4 m;
    m.rotate(pose_.rotation.conjugated());
    m.translate(-eye());
    return m;
}

QMatrix4x4 OrbitCamera::projection(float aspect) const
{
    QMatrix4x4 m;
    // Near and far follow the distance so the depth buffer keeps its precision at every zoom.
    m.perspective(kFieldOfViewDeg, aspect, std::max(0.005f, 0.02f * pose_.distance),
                  20.0f * pose_.distance + 10.0f);
    return m;
}

Ray OrbitCamera::ray(QPointF ndc, float aspect) const
{
    const float t = std::tan(radians(kFieldOfViewDeg) / 2.0f);
    const QVector3D local(static_cast<float>(ndc.x()) * t * aspect, static_cast<float>(ndc.y()) * t, -1.0f);
    return Ray{eye(), pose_.rotation.rotatedVector(local).normalized()};
}

std::optional<QPointF> OrbitCamera::project(const QVector3D& world, float aspect) const
{
    const QVector4D clip = projection(aspect) * viewMatrix() * QVector4D(world, 1.0f);
    if (clip.w() <= 1e-6f) return std::nullopt;
    return QPointF(clip.x() / clip.w(), clip.y() / clip.w());
}

CameraPose OrbitCamera::presetPose(CameraPreset preset, const PresetFrame& frame)
{
    const float t = std::tan(radians(kFieldOfViewDeg) / 2.0f);
    const QPointF c = frame.extent.center();
    const QVector3D centre(static_cast<float>(c.x()), static_cast<float>(c.y()), 0.0f);
    const float halfLength = static_cast<float>(frame.extent.width()) / 2.0f;
    const float halfWidth = static_cast<float>(frame.extent.height()) / 2.0f;
    const float aspect = std::max(frame.aspect, 0.1f);
    CameraPose pose;
    switch (preset) {
    case CameraPreset::Top:
        pose.target = centre;
        pose.rotation = rotationFrom(QVector3D(1.0f, 0.0f, 0.0f), 90.0f);
        // Fit both extents, with 4 % to spare.
        pose.distance = 1.04f * std::max(halfWidth / t, halfLength / (t * aspect));
        break;
    case CameraPreset::Player: {
        const float h = radians(frame.headingDeg);
        const QVector3D along(std::cos(h), std::sin(h), 0.0f);
        // Look at a point a little ahead of the cue ball, from behind it at a player's eye height.
        pose.target = frame.focus + 0.45f * along;
        pose.target.setZ(0.0f);
        pose.rotation = rotationLookingAlong(frame.headingDeg, 16.0f);
        pose.distance = 1.25f;
        break;
    }
    case CameraPreset::Side:
        pose.target = centre;
        pose.rotation = rotationLookingAlong(90.0f, 26.0f);
        pose.distance = 0.9f * halfLength / (t * aspect);
        pose.distance = fittingDistance(pose, frame.extent, aspect);
        break;
    }
    return constrained(pose);
}

void OrbitCamera::transitionTo(const CameraPose& to, float durationS)
{
    if (durationS <= 0.0f) {
        setPose(to);
        return;
    }
    transition_ = Transition{pose_, constrained(to), durationS, 0.0f};
}

bool OrbitCamera::advance(float dtS)
{
    if (!transition_) return false;
    Transition& tr = *transition_;
    tr.elapsedS += dtS;
    const float s = smoothstep(tr.elapsedS / tr.durationS);
    CameraPose p;
    p.target = tr.from.target + s * (tr.to.target - tr.from.target);
    // Geometric interpolation of the distance: zooming feels uniform.
    p.distance = tr.from.distance * std::pow(tr.to.distance / tr.from.distance, s);
    p.rotation = QQuaternion::slerp(tr.from.rotation, tr.to.rotation, s);
    const bool done = tr.elapsedS >= tr.durationS;
    pose_ = constrained(done ? tr.to : p);
    if (done) transition_.reset();
    return !done;
}

}  // namespace cuelab
