#pragma once
// Keeps a lesson's questions on their balls while the setup is edited: a renamed ball keeps its
// questions under its new id, a removed ball leaves them (a question that asked only about it then
// asks about its event's own balls). Applied by the editor to every edit, so that a setup the editor
// holds always saves and loads again (the loader refuses questions naming a ball the setup lacks).

#include "Setup.h"

namespace cuelab::lesson {

// `after` is the edited setup, `before` the setup it was made from. Balls are matched by index when
// both setups have as many balls (a rename), else by id (an addition or removal).
void followBallIds(const Setup& before, Setup& after);

}  // namespace cuelab::lesson
