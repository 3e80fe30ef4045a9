#pragma once

#include <QString>

namespace cuelab {

// The OpenGL version the table view needs (core profile).
inline constexpr int kGlMajor = 3;
inline constexpr int kGlMinor = 3;

// Tries to create an OpenGL 3.3 core context on an offscreen surface. Returns false with a
// message a person can act on when that is impossible (no display driver, too old a GL).
bool probeOpenGL(QString* message);

}  // namespace cuelab
