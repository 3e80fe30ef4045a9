#include "ShaderLibrary.h"

#include <QFile>
#include <QOpenGLShaderProgram>
#include <QVector2D>

namespace cuelab {

namespace {

// The source of a shader file with `define` (if any) defined right after its #version line.
QByteArray shaderSource(const QString& path, const QByteArray& define)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) return {};
    QByteArray source = file.readAll();
    if (!define.isEmpty()) {
        const qsizetype endOfVersion = source.indexOf('\n') + 1;
        source.insert(endOfVersion, "#define " + define + "\n");
    }
    return source;
}

std::unique_ptr<QOpenGLShaderProgram> makeProgram(const QString& name, bool geometry, QString* error,
                                                  const QByteArray& define = {})
{
    auto program = std::make_unique<QOpenGLShaderProgram>();
    const QString base = QStringLiteral(":/shaders/") + name;
    bool ok = program->addShaderFromSourceCode(QOpenGLShader::Vertex, shaderSource(base + QStringLiteral(".vert"), {})) &&
              (!geometry ||
               program->addShaderFromSourceCode(QOpenGLShader::Geometry, shaderSource(base + QStringLiteral(".geom"), {}))) &&
              program->addShaderFromSourceCode(QOpenGLShader::Fragment, shaderSource(base + QStringLiteral(".frag"), define)) &&
              program->link();
    if (!ok) {
        if (error) *error = QStringLiteral("The %1 shader did not build: %2").arg(name, program->log());
        return nullptr;
    }
    return program;
}

}  // namespace

bool ShaderLibrary::build(QString* error)
{
    return (table = makeProgram(QStringLiteral("table"), false, error)) &&
           (tableCut = makeProgram(QStringLiteral("table"), false, error, "CUT_POCKETS")) &&
           (ball = makeProgram(QStringLiteral("ball"), false, error)) &&
           (ghost = makeProgram(QStringLiteral("ball"), false, error, "GHOST")) &&
           (shadow = makeProgram(QStringLiteral("shadow"), false, error)) &&
           (line = makeProgram(QStringLiteral("line"), true, error));
}

void ShaderLibrary::reset()
{
    for (auto* program : {&table, &tableCut, &ball, &ghost, &shadow, &line}) program->reset();
}

std::array<QVector3D, 2> lampPositions(const Table& table)
{
    const auto L = static_cast<float>(table.length), W = static_cast<float>(table.width);
    return {QVector3D(0.25f * L, 0.5f * W, 1.1f), QVector3D(0.75f * L, 0.5f * W, 1.1f)};
}

void bindBallProgram(QOpenGLShaderProgram& program, const RenderFrame& frame, const std::array<QVector3D, 2>& lamps)
{
    program.bind();
    program.setUniformValue("uViewProjection", frame.viewProjection);
    program.setUniformValue("uEye", frame.eye);
    program.setUniformValue("uCameraUp", frame.cameraUp);
    program.setUniformValue("uPixelAngle", frame.pixelAngle);
    program.setUniformValueArray("uLights", lamps.data(), 2);
    program.setUniformValue("uDigits", 0);
}

void bindLineProgram(QOpenGLShaderProgram& program, const RenderFrame& frame)
{
    program.bind();
    program.setUniformValue("uViewProjection", frame.viewProjection);
    program.setUniformValue("uViewport", QVector2D(static_cast<float>(frame.viewportPixels.width()),
                                                   static_cast<float>(frame.viewportPixels.height())));
    program.setUniformValue("uTime", static_cast<float>(frame.time));
}

}  // namespace cuelab
