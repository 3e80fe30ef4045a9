#include "TablePass.h"

#include "CueStickMesh.h"
#include "TableMesh.h"

#include <QOpenGLFramebufferObject>
#include <QOpenGLShaderProgram>
#include <QVector2D>

#include <array>
#include <cstddef>

namespace cuelab {

namespace {

const void* offset(std::size_t bytes) { return reinterpret_cast<const void*>(bytes); }

// A vertex array over a buffer of MeshVertex.
void meshLayout(QOpenGLExtraFunctions& gl, GlVertexArray& vao, GlBuffer& vbo)
{
    gl.glBindVertexArray(vao.create());
    gl.glBindBuffer(GL_ARRAY_BUFFER, vbo.create());
    const auto stride = static_cast<GLsizei>(sizeof(MeshVertex));
    gl.glEnableVertexAttribArray(0);
    gl.glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, offset(offsetof(MeshVertex, position)));
    gl.glEnableVertexAttribArray(1);
    gl.glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, offset(offsetof(MeshVertex, normal)));
    gl.glEnableVertexAttribArray(2);
    gl.glVertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, stride, offset(offsetof(MeshVertex, colour)));
    gl.glEnableVertexAttribArray(3);
    gl.glVertexAttribPointer(3, 1, GL_FLOAT, GL_FALSE, stride, offset(offsetof(MeshVertex, material)));
}

bool sameTable(const Table& a, const Table& b)
{
    return a.kind == b.kind && a.length == b.length && a.width == b.width && a.cushionHeight == b.cushionHeight &&
           a.pockets.size() == b.pockets.size();
}

}  // namespace

TablePass::TablePass() = default;
TablePass::~TablePass() = default;

void TablePass::create()
{
    QOpenGLExtraFunctions* gl = currentGl();
    if (!gl) return;
    meshLayout(*gl, tableVao_, tableVbo_);
    meshLayout(*gl, cueVao_, cueVbo_);
    const std::vector<MeshVertex> cue = buildCueStickMesh();
    gl->glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(cue.size() * sizeof(MeshVertex)), cue.data(), GL_STATIC_DRAW);
    cueCount_ = static_cast<int>(cue.size());
    gl->glBindVertexArray(0);
    dirty_ = true;
}

void TablePass::reset()
{
    tableVao_.reset();
    cueVao_.reset();
    tableVbo_.reset();
    cueVbo_.reset();
    cache_.reset();
    multisampled_.reset();
    cacheGeneration_ = -1;
    hasLastFrame_ = false;
    dirty_ = true;
}

void TablePass::setTable(const Table& table)
{
    if (hasTable_ && sameTable(table_, table)) return;
    table_ = table;
    hasTable_ = true;
    dirty_ = true;
}

void TablePass::invalidateCache() { cacheGeneration_ = -1; }

void TablePass::upload()
{
    QOpenGLExtraFunctions* gl = currentGl();
    std::vector<MeshVertex> mesh = buildTableMesh(table_);
    tableUncutCount_ = static_cast<int>(partitionByPocketCut(table_, mesh));
    gl->glBindBuffer(GL_ARRAY_BUFFER, tableVbo_.id());
    gl->glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.size() * sizeof(MeshVertex)), mesh.data(), GL_STATIC_DRAW);
    tableCount_ = static_cast<int>(mesh.size());
    dirty_ = false;
    ++generation_;
}

bool TablePass::cacheValid(const RenderFrame& frame, int samples, const std::optional<QMatrix4x4>& cue) const
{
    return cache_ && cache_->isValid() && cacheGeneration_ == generation_ && cacheSamples_ == samples &&
           cacheCue_ == cue && cache_->size() == frame.viewportPixels && cacheViewProjection_ == frame.viewProjection;
}

// Draws the table (and the cue) into the cache. A multisampled target gets a cache with its own
// samples; a single-sampled one (the view's, whose balls and lines antialias themselves) gets the
// table drawn 4x multisampled and resolved once, so that its edges stay smooth at the cost of one
// single-sampled copy per frame.
void TablePass::buildCache(const RenderFrame& frame, ShaderLibrary& shaders, int samples,
                           const std::optional<QMatrix4x4>& cue, unsigned int target)
{
    QOpenGLExtraFunctions* gl = currentGl();
    auto makeFbo = [&frame](int fboSamples) {
        QOpenGLFramebufferObjectFormat format;
        format.setAttachment(QOpenGLFramebufferObject::CombinedDepthStencil);  // as QOpenGLWidget's
        format.setSamples(fboSamples);
        return std::make_unique<QOpenGLFramebufferObject>(frame.viewportPixels, format);
    };
    if (!cache_ || cache_->size() != frame.viewportPixels || cacheSamples_ != samples) {
        cache_ = makeFbo(samples);
        cacheSamples_ = samples;
    }
    const bool resolve = samples == 0;
    if (resolve && (!multisampled_ || multisampled_->size() != frame.viewportPixels)) multisampled_ = makeFbo(kTableSamples);
    if (!resolve) multisampled_.reset();
    cacheGeneration_ = -1;
    QOpenGLFramebufferObject* drawInto = resolve ? multisampled_.get() : cache_.get();
    if (!cache_->isValid() || !drawInto->isValid()) return;
    gl->glBindFramebuffer(GL_FRAMEBUFFER, drawInto->handle());
    gl->glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    drawTable(frame, shaders);
    if (cue) drawCue(frame, shaders, *cue);
    if (resolve) {
        const int w = frame.viewportPixels.width(), h = frame.viewportPixels.height();
        gl->glBindFramebuffer(GL_READ_FRAMEBUFFER, multisampled_->handle());
        gl->glBindFramebuffer(GL_DRAW_FRAMEBUFFER, cache_->handle());
        gl->glBlitFramebuffer(0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    }
    gl->glBindFramebuffer(GL_FRAMEBUFFER, target);
    cacheViewProjection_ = frame.viewProjection;
    cacheGeneration_ = generation_;
    cacheCue_ = cue;
}

void TablePass::drawCue(const RenderFrame& frame, ShaderLibrary& shaders, const QMatrix4x4& model)
{
    const std::array<QVector3D, 2> lamps = lampPositions(table_);
    QOpenGLShaderProgram& program = *shaders.table;
    program.bind();
    program.setUniformValue("uViewProjection", frame.viewProjection);
    program.setUniformValue("uEye", frame.eye);
    program.setUniformValueArray("uLights", lamps.data(), 2);
    program.setUniformValue("uModel", model);
    QOpenGLExtraFunctions* gl = currentGl();
    gl->glBindVertexArray(cueVao_.id());
    gl->glDrawArrays(GL_TRIANGLES, 0, cueCount_);
}

// The table: the part no pocket reaches without the pocket cut, the rest with it.
void TablePass::drawTable(const RenderFrame& frame, ShaderLibrary& shaders)
{
    const Table& t = table_;
    const auto L = static_cast<float>(t.length), W = static_cast<float>(t.width);
    const std::array<QVector3D, 2> lamps = lampPositions(t);
    std::array<QVector3D, 6> pockets{};
    const int pocketCount = t.pockets.size() == 6 ? 6 : 0;
    // The pockets by place (table.frag looks up one by the fragment's sixth of the table): bottom
    // left, middle, right, then the top row; each slot takes the pocket nearest to its place.
    for (int slot = 0; slot < pocketCount; ++slot) {
        const Vec2 place(t.length * (slot % 3) / 2.0, t.width * (slot / 3));
        const Pocket* nearest = &t.pockets.front();
        for (const Pocket& p : t.pockets)
            if ((p.centre - place).norm() < (nearest->centre - place).norm()) nearest = &p;
        pockets[static_cast<std::size_t>(slot)] = QVector3D(
            static_cast<float>(nearest->centre.x()), static_cast<float>(nearest->centre.y()), static_cast<float>(nearest->radius));
    }
    QOpenGLExtraFunctions* gl = currentGl();
    gl->glBindVertexArray(tableVao_.id());
    for (QOpenGLShaderProgram* program : {shaders.tableCut.get(), shaders.table.get()}) {
        program->bind();
        program->setUniformValue("uViewProjection", frame.viewProjection);
        program->setUniformValue("uModel", QMatrix4x4());
        program->setUniformValue("uEye", frame.eye);
        program->setUniformValueArray("uLights", lamps.data(), 2);
        program->setUniformValueArray("uPockets", pockets.data(), 6);
        program->setUniformValue("uPocketCount", pocketCount);
        program->setUniformValue("uTableSize", QVector2D(L, W));
        if (program == shaders.tableCut.get()) gl->glDrawArrays(GL_TRIANGLES, tableUncutCount_, tableCount_ - tableUncutCount_);
        else gl->glDrawArrays(GL_TRIANGLES, 0, tableUncutCount_);
    }
}

bool TablePass::draw(const RenderFrame& frame, ShaderLibrary& shaders, const std::optional<QMatrix4x4>& cue,
                     unsigned int target)
{
    QOpenGLExtraFunctions* gl = currentGl();
    if (!hasTable_) {
        gl->glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        return false;
    }
    if (dirty_) upload();
    GLint samples = 0;
    gl->glGetIntegerv(GL_SAMPLES, &samples);
    const bool moving = hasLastFrame_ && lastViewProjection_ != frame.viewProjection;
    // The cue moves with a drag of the struck ball or of the aim: the cache then keeps the table alone
    // and the stick is drawn over it each frame without multisampling, until it stands still again.
    const bool cueMoving = hasLastFrame_ && cue && lastCue_ != cue;
    lastViewProjection_ = frame.viewProjection;
    lastCue_ = cue;
    hasLastFrame_ = true;
    const std::optional<QMatrix4x4> cachedCue = cueMoving ? std::nullopt : cue;
    if (!moving && !cacheValid(frame, samples, cachedCue)) buildCache(frame, shaders, samples, cachedCue, target);
    const bool cached = cacheValid(frame, samples, cachedCue);
    if (cached) {
        const int w = frame.viewportPixels.width(), h = frame.viewportPixels.height();
        gl->glBindFramebuffer(GL_READ_FRAMEBUFFER, cache_->handle());
        gl->glBindFramebuffer(GL_DRAW_FRAMEBUFFER, target);
        gl->glBlitFramebuffer(0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT, GL_NEAREST);
        gl->glBindFramebuffer(GL_FRAMEBUFFER, target);
        if (cue && !cachedCue) drawCue(frame, shaders, *cue);
    } else {
        gl->glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        drawTable(frame, shaders);
        if (cue) drawCue(frame, shaders, *cue);
    }
    // One more still frame draws what moved antialiased (not when the cache failed: that would
    // repaint for ever).
    return (moving && !cached) || (cueMoving && cached);
}

}  // namespace cuelab
