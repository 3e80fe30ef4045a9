#pragma once
// The renderer's shader programs (resources/shaders), built once per context, and the uniforms the
// ball programs share. Context current in every call.

#include "RenderFrame.h"
#include "Table.h"

#include <QString>
#include <QVector3D>

#include <array>
#include <memory>

class QOpenGLShaderProgram;

namespace cuelab {

struct ShaderLibrary {
    std::unique_ptr<QOpenGLShaderProgram> table, tableCut, ball, ghost, shadow, line;

    bool build(QString* error);  // false with a message naming the shader that did not build
    void reset();
};

// Two lamps 1.1 m above the cloth, over the quarter points of the long axis.
std::array<QVector3D, 2> lampPositions(const Table& table);

// Binds a ball program (ball or ghost) with the frame's camera and the lamps; texture unit 0 holds
// the digit atlas.
void bindBallProgram(QOpenGLShaderProgram& program, const RenderFrame& frame, const std::array<QVector3D, 2>& lamps);

// Binds the line program with the frame's camera, viewport and time.
void bindLineProgram(QOpenGLShaderProgram& program, const RenderFrame& frame);

}  // namespace cuelab
