#pragma once
// The table view's camera: it orbits a target point at a distance, its orientation a unit quaternion.
// Orbiting multiplies the quaternion by axis-angle rotations (about the world's vertical for yaw,
// about the camera's right axis for pitch), as in Qt's trackball examples, then re-orthonormalises it
// under one constraint: the camera's right axis stays horizontal, so the table's up is always up on
// screen (no roll, and none can accumulate over thousands of small orbits). There are no Euler angles
// and no gimbal lock: looking straight down is a regular pose.
//
// Plain class without GL: the view converts mouse motion into calls and asks for matrices and rays.
// World frame = table frame of PHYSICS.md (x along the length, y along the width, z up), metres.

#include "ViewScene.h"

#include <QMatrix4x4>
#include <QPointF>
#include <QQuaternion>
#include <QRectF>
#include <QVector3D>

#include <optional>

namespace cuelab {

struct CameraPose {
    QVector3D target{0.0f, 0.0f, 0.0f};  // m, the point orbited and looked at
    float distance = 3.0f;               // m, from the eye to the target
    QQuaternion rotation;                // camera frame -> world frame; the camera looks along its -z
};

// A half-line from the eye through a point of the image.
struct Ray {
    QVector3D origin;     // m
    QVector3D direction;  // unit
};

// What the presets frame.
struct PresetFrame {
    QRectF extent{0.0, 0.0, 2.54, 1.27};  // m, everything that should fit (the table with its rails)
    QVector3D focus{0.0f, 0.0f, 0.0f};    // m, the cue ball, which the player view stands behind
    float headingDeg = 0.0f;              // degrees, where the player view looks (the shot's heading)
    float aspect = 1.6f;                  // width / height of the image
};

class OrbitCamera {
public:
    static constexpr float kFieldOfViewDeg = 40.0f;   // degrees, vertical
    static constexpr float kMinElevationDeg = 2.0f;   // degrees: never under the cloth
    static constexpr float kMaxElevationDeg = 90.0f;  // degrees: straight down, not beyond (no flip)
    static constexpr float kMinDistance = 0.05f;      // m
    static constexpr float kMaxDistance = 50.0f;      // m

    const CameraPose& pose() const { return pose_; }
    void setPose(const CameraPose& pose);  // applies the constraints; stops a running transition

    QVector3D target() const { return pose_.target; }
    float distance() const { return pose_.distance; }
    QQuaternion rotation() const { return pose_.rotation; }
    QVector3D eye() const;
    QVector3D right() const;    // unit, horizontal
    QVector3D up() const;       // unit, the screen's up
    QVector3D forward() const;  // unit, the line of sight
    float elevationDeg() const; // degrees, angle of the line of sight below the horizontal

    // Yaw about the world vertical through the target, then pitch about the camera's right axis
    // (positive pitch raises the eye), pitch limited to [kMinElevationDeg, kMaxElevationDeg].
    void orbit(float yawDeg, float pitchDeg);
    // Moves the target so that the point of the plane z = target.z under `fromNdc` ends up under
    // `toNdc` (the cloth follows the cursor). Falls back to a screen-plane move when the plane is
    // seen edge-on.
    void pan(QPointF fromNdc, QPointF toNdc, float aspect);
    // Scales the eye's offset from `point` by `factor` (< 1 approaches): `point` keeps its place in
    // the image, so the wheel zooms towards what is under the cursor.
    void zoomTowards(const QVector3D& point, float factor);
    // Looks at `point` from the same direction and distance (double-click).
    void centreOn(const QVector3D& point);

    QMatrix4x4 viewMatrix() const;
    QMatrix4x4 projection(float aspect) const;
    // The ray from the eye through a point of the image in normalised device coordinates
    // ([-1, 1]^2, y up).
    Ray ray(QPointF ndc, float aspect) const;
    // Where a world point lands in normalised device coordinates; nullopt behind the eye.
    std::optional<QPointF> project(const QVector3D& world, float aspect) const;

    static CameraPose presetPose(CameraPreset preset, const PresetFrame& frame);

    // A smooth move to `to` over `durationS` (spherical interpolation of the rotation, eased).
    void transitionTo(const CameraPose& to, float durationS);
    // Advances a running transition by `dtS`; returns true while one is running.
    bool advance(float dtS);
    bool isTransitioning() const { return transition_.has_value(); }

private:
    static CameraPose constrained(CameraPose pose);

    struct Transition {
        CameraPose from;
        CameraPose to;
        float durationS = 0.0f;
        float elapsedS = 0.0f;
    };

    CameraPose pose_ = constrained(CameraPose{});
    std::optional<Transition> transition_;
};

}  // namespace cuelab
