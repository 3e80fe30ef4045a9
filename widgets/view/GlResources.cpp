#include "GlResources.h"

#include <QOpenGLContext>
#include <QOpenGLShaderProgram>

#include <algorithm>

namespace cuelab {

namespace {

const void* offset(std::size_t bytes) { return reinterpret_cast<const void*>(bytes); }

}  // namespace

QOpenGLExtraFunctions* currentGl()
{
    QOpenGLContext* context = QOpenGLContext::currentContext();
    return context ? context->extraFunctions() : nullptr;
}

template <GlKind kind>
unsigned int GlHandle<kind>::create()
{
    reset();
    if (QOpenGLExtraFunctions* gl = currentGl()) {
        if constexpr (kind == GlKind::Buffer) gl->glGenBuffers(1, &id_);
        else if constexpr (kind == GlKind::VertexArray) gl->glGenVertexArrays(1, &id_);
        else gl->glGenTextures(1, &id_);
    }
    return id_;
}

template <GlKind kind>
void GlHandle<kind>::reset()
{
    if (id_ == 0) return;
    if (QOpenGLExtraFunctions* gl = currentGl()) {
        if constexpr (kind == GlKind::Buffer) gl->glDeleteBuffers(1, &id_);
        else if constexpr (kind == GlKind::VertexArray) gl->glDeleteVertexArrays(1, &id_);
        else gl->glDeleteTextures(1, &id_);
    }
    id_ = 0;
}

template class GlHandle<GlKind::Buffer>;
template class GlHandle<GlKind::VertexArray>;
template class GlHandle<GlKind::Texture>;

void uploadGrowing(QOpenGLExtraFunctions& gl, std::size_t& capacity, const void* data, std::size_t bytes)
{
    if (bytes > capacity) {
        capacity = std::max(bytes, 2 * capacity);
        gl.glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(capacity), nullptr, GL_DYNAMIC_DRAW);
    }
    if (bytes > 0) gl.glBufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(bytes), data);
}

void LineBatch::create()
{
    QOpenGLExtraFunctions* gl = currentGl();
    if (!gl) return;
    gl->glBindVertexArray(vao_.create());
    gl->glBindBuffer(GL_ARRAY_BUFFER, vbo_.create());
    const auto stride = static_cast<GLsizei>(sizeof(LineVertex));
    gl->glEnableVertexAttribArray(0);
    gl->glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, offset(offsetof(LineVertex, position)));
    gl->glEnableVertexAttribArray(1);
    gl->glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, stride, offset(offsetof(LineVertex, colour)));
    gl->glEnableVertexAttribArray(2);
    gl->glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, stride, offset(offsetof(LineVertex, time)));
    gl->glBindVertexArray(0);
    capacityBytes_ = 0;
    count_ = 0;
}

void LineBatch::reset()
{
    vao_.reset();
    vbo_.reset();
    capacityBytes_ = 0;
    count_ = 0;
}

void LineBatch::upload(const std::vector<LineVertex>& vertices)
{
    QOpenGLExtraFunctions* gl = currentGl();
    if (!gl || !vbo_) return;
    gl->glBindBuffer(GL_ARRAY_BUFFER, vbo_.id());
    uploadGrowing(*gl, capacityBytes_, vertices.data(), vertices.size() * sizeof(LineVertex));
    count_ = static_cast<int>(vertices.size());
}

void LineBatch::draw(QOpenGLShaderProgram& program, float widthPx, float pastAlpha, float futureAlpha,
                     float dashPeriod, int first, int count) const
{
    if (count < 0) count = count_ - first;
    if (count <= 0 || (pastAlpha <= 0.0f && futureAlpha <= 0.0f)) return;
    QOpenGLExtraFunctions* gl = currentGl();
    if (!gl) return;
    program.setUniformValue("uWidth", widthPx);
    program.setUniformValue("uPastAlpha", pastAlpha);
    program.setUniformValue("uFutureAlpha", futureAlpha);
    program.setUniformValue("uDashPeriod", dashPeriod);
    gl->glBindVertexArray(vao_.id());
    gl->glDrawArrays(GL_LINES, first, count);
}

void BallBatch::create(unsigned int quadVbo)
{
    QOpenGLExtraFunctions* gl = currentGl();
    if (!gl) return;
    gl->glBindVertexArray(vao_.create());
    gl->glBindBuffer(GL_ARRAY_BUFFER, quadVbo);
    gl->glEnableVertexAttribArray(0);
    gl->glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), offset(0));
    gl->glBindBuffer(GL_ARRAY_BUFFER, instances_.create());
    for (unsigned int k = 0; k < 4; ++k) {
        gl->glEnableVertexAttribArray(1 + k);
        gl->glVertexAttribPointer(1 + k, 4, GL_FLOAT, GL_FALSE, kFloatsPerBall * sizeof(float),
                                  offset(4 * k * sizeof(float)));
        gl->glVertexAttribDivisor(1 + k, 1);
    }
    gl->glBindVertexArray(0);
    capacityBytes_ = 0;
    count_ = 0;
}

void BallBatch::reset()
{
    vao_.reset();
    instances_.reset();
    capacityBytes_ = 0;
    count_ = 0;
}

void BallBatch::upload(const std::vector<float>& instances)
{
    QOpenGLExtraFunctions* gl = currentGl();
    if (!gl || !instances_) return;
    gl->glBindBuffer(GL_ARRAY_BUFFER, instances_.id());
    uploadGrowing(*gl, capacityBytes_, instances.data(), instances.size() * sizeof(float));
    count_ = static_cast<int>(instances.size() / kFloatsPerBall);
}

void BallBatch::draw() const
{
    if (count_ == 0) return;
    QOpenGLExtraFunctions* gl = currentGl();
    if (!gl) return;
    gl->glBindVertexArray(vao_.id());
    gl->glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, count_);
}

void appendBallInstance(std::vector<float>& out, const QVector3D& centre, float radius, const float quaternion[4],
                        const QVector3D& colour, int number, bool striped, bool dotted, bool highlighted, float alpha)
{
    out.insert(out.end(), {centre.x(), centre.y(), centre.z(), radius, quaternion[0], quaternion[1], quaternion[2],
                           quaternion[3], colour.x(), colour.y(), colour.z(), static_cast<float>(number),
                           striped ? 1.0f : 0.0f, dotted ? 1.0f : 0.0f, highlighted ? 1.0f : 0.0f, alpha});
}

}  // namespace cuelab
