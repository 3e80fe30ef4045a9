#pragma once
// What the camera presets frame for a scene: the whole table with its rails, and for the player's
// view the struck ball and the shot's heading (the cue ball along +x when there is no shot).

#include "OrbitCamera.h"
#include "ViewScene.h"

namespace cuelab {

PresetFrame presetFrameFor(const ViewScene& scene, float aspect);

}  // namespace cuelab
