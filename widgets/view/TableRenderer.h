#pragma once
// Draws a ViewScene with OpenGL 3.3 core into the current framebuffer (FIRST CUT: declaration only).

namespace cuelab {

class TableRenderer {
};

}  // namespace cuelab
