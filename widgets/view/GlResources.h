#pragma once
// RAII owners of OpenGL objects for the renderer's passes, and the two kinds of batch they draw: line
// segments (widened to quads by line.geom) and instanced ball impostors.
//
// A handle deletes its object when it is reset or destroyed, through the context current at that
// moment; with no current context (the context went away first) it only forgets the name. The
// renderer resets its handles in release(), with its context current, so nothing leaks in practice.

#include "OverlayLines.h"

#include <QOpenGLExtraFunctions>

#include <cstddef>
#include <utility>
#include <vector>

class QOpenGLShaderProgram;

namespace cuelab {

// The current context's OpenGL 3.3 functions (nullptr when no context is current).
QOpenGLExtraFunctions* currentGl();

enum class GlKind { Buffer, VertexArray, Texture };

template <GlKind kind>
class GlHandle {
public:
    GlHandle() = default;
    ~GlHandle() { reset(); }
    GlHandle(const GlHandle&) = delete;
    GlHandle& operator=(const GlHandle&) = delete;
    GlHandle(GlHandle&& other) noexcept : id_(std::exchange(other.id_, 0u)) {}
    GlHandle& operator=(GlHandle&& other) noexcept
    {
        if (this != &other) {
            reset();
            id_ = std::exchange(other.id_, 0u);
        }
        return *this;
    }

    // Deletes any old object and creates a new one; its name (0 when no context is current).
    unsigned int create();
    void reset();
    unsigned int id() const { return id_; }
    explicit operator bool() const { return id_ != 0; }

private:
    unsigned int id_ = 0;
};

using GlBuffer = GlHandle<GlKind::Buffer>;
using GlVertexArray = GlHandle<GlKind::VertexArray>;
using GlTexture = GlHandle<GlKind::Texture>;

extern template class GlHandle<GlKind::Buffer>;
extern template class GlHandle<GlKind::VertexArray>;
extern template class GlHandle<GlKind::Texture>;

// Uploads `bytes` into the buffer bound to GL_ARRAY_BUFFER, growing its storage geometrically
// (`capacity` in bytes, kept by the caller) so that a frame-to-frame load settles without
// reallocating every frame.
void uploadGrowing(QOpenGLExtraFunctions& gl, std::size_t& capacity, const void* data, std::size_t bytes);

// Line segments (pairs of LineVertex) in one buffer, drawn with the line program.
class LineBatch {
public:
    void create();  // context current
    void reset();
    void upload(const std::vector<LineVertex>& vertices);
    int count() const { return count_; }
    // The line program must be bound with its per-frame uniforms set. widthPx in framebuffer pixels.
    void draw(QOpenGLShaderProgram& program, float widthPx, float pastAlpha, float futureAlpha, float dashPeriod,
              int first = 0, int count = -1) const;

private:
    GlVertexArray vao_;
    GlBuffer vbo_;
    std::size_t capacityBytes_ = 0;
    int count_ = 0;
};

// Ball impostors: the shared unit quad, instanced with kFloatsPerBall floats per ball.
inline constexpr int kFloatsPerBall = 16;  // centre + radius, orientation, colour + number, flags

class BallBatch {
public:
    void create(unsigned int quadVbo);  // context current
    void reset();
    void upload(const std::vector<float>& instances);  // kFloatsPerBall per ball
    int count() const { return count_; }
    unsigned int instanceBuffer() const { return instances_.id(); }
    void draw() const;  // the ball program bound

private:
    GlVertexArray vao_;
    GlBuffer instances_;
    std::size_t capacityBytes_ = 0;
    int count_ = 0;
};

// One ball instance: centre (x, y, z) and radius, orientation quaternion (x, y, z, w), colour and
// number, and the flags striped, dotted, highlighted, alpha.
void appendBallInstance(std::vector<float>& out, const QVector3D& centre, float radius, const float quaternion[4],
                        const QVector3D& colour, int number, bool striped, bool dotted, bool highlighted, float alpha);

}  // namespace cuelab
