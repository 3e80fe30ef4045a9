#include "TableRenderer.h"

#include "CueStickMesh.h"
#include "OrbitCamera.h"
#include "TableMesh.h"

#include <QFile>
#include <QImage>
#include <QOpenGLFramebufferObject>
#include <QOpenGLShaderProgram>
#include <QPainter>
#include <QVector2D>

#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>

namespace cuelab {

namespace {

constexpr int kFloatsPerBall = 16;  // centre + radius, orientation, colour + number, flags
constexpr int kDigitCell = 128;     // pixels per digit cell of the 4 x 4 atlas

const void* offset(std::size_t bytes) { return reinterpret_cast<const void*>(bytes); }

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

void putQuaternion(float* out, const Eigen::Quaterniond& q)
{
    out[0] = static_cast<float>(q.x());
    out[1] = static_cast<float>(q.y());
    out[2] = static_cast<float>(q.z());
    out[3] = static_cast<float>(q.w());
}

// Places the cue stick (built along +x from its tip) behind the struck ball: the tip 2 cm from the
// contact point given by the shot's side and height offsets, the butt raised by the elevation.
std::optional<QMatrix4x4> cuePlacement(const SimulationResult& result, const CueStrike& shot)
{
    const int index = result.ballIndex(shot.ball);
    if (index < 0) return std::nullopt;
    const Ball& ball = result.balls[static_cast<std::size_t>(index)];
    const double r = ball.radius;
    const double h = shot.headingDeg * std::numbers::pi / 180.0, e = shot.elevationDeg * std::numbers::pi / 180.0;
    const QVector3D d(static_cast<float>(std::cos(h)), static_cast<float>(std::sin(h)), 0.0f);
    const QVector3D right(d.y(), -d.x(), 0.0f);  // the player's right, looking along d
    const QVector3D up(0.0f, 0.0f, 1.0f);
    const double a = std::clamp(shot.side, -0.9, 0.9) * r, b = std::clamp(shot.height, -0.9, 0.9) * r;
    const double depth = std::sqrt(std::max(0.0, r * r - a * a - b * b));
    const QVector3D centre(static_cast<float>(ball.state.position.x()), static_cast<float>(ball.state.position.y()),
                           static_cast<float>(r));
    const QVector3D contact = centre - static_cast<float>(depth) * d + static_cast<float>(a) * right + static_cast<float>(b) * up;
    const QVector3D along = -static_cast<float>(std::cos(e)) * d + static_cast<float>(std::sin(e)) * up;  // tip -> butt
    const QVector3D side = QVector3D::crossProduct(up, along).normalized();
    const QVector3D third = QVector3D::crossProduct(along, side);
    const QVector3D tip = contact + 0.02f * along;
    QMatrix4x4 m;
    m.setColumn(0, QVector4D(along, 0.0f));
    m.setColumn(1, QVector4D(side, 0.0f));
    m.setColumn(2, QVector4D(third, 0.0f));
    m.setColumn(3, QVector4D(tip, 1.0f));
    return m;
}

// Two lamps 1.1 m above the cloth, over the quarter points of the long axis.
std::array<QVector3D, 2> lampPositions(const Table& table)
{
    const auto L = static_cast<float>(table.length), W = static_cast<float>(table.width);
    return {QVector3D(0.25f * L, 0.5f * W, 1.1f), QVector3D(0.75f * L, 0.5f * W, 1.1f)};
}

}  // namespace

float pixelAngle(int heightPixels)
{
    const float halfFov = OrbitCamera::kFieldOfViewDeg / 2.0f * std::numbers::pi_v<float> / 180.0f;
    return 2.0f * std::tan(halfFov) / static_cast<float>(std::max(1, heightPixels));
}

TableRenderer::TableRenderer() = default;
TableRenderer::~TableRenderer() = default;

bool TableRenderer::initialize(QString* error)
{
    initializeOpenGLFunctions();
    tableProgram_ = makeProgram(QStringLiteral("table"), false, error);
    if (!tableProgram_) return false;
    tableCutProgram_ = makeProgram(QStringLiteral("table"), false, error, "CUT_POCKETS");
    if (!tableCutProgram_) return false;
    ballProgram_ = makeProgram(QStringLiteral("ball"), false, error);
    if (!ballProgram_) return false;
    ghostProgram_ = makeProgram(QStringLiteral("ball"), false, error, "GHOST");
    if (!ghostProgram_) return false;
    shadowProgram_ = makeProgram(QStringLiteral("shadow"), false, error);
    if (!shadowProgram_) return false;
    lineProgram_ = makeProgram(QStringLiteral("line"), true, error);
    if (!lineProgram_) return false;

    // Table and cue: MeshVertex layout.
    auto meshVao = [this](unsigned int& vao, unsigned int& vbo) {
        glGenVertexArrays(1, &vao);
        glGenBuffers(1, &vbo);
        glBindVertexArray(vao);
        glBindBuffer(GL_ARRAY_BUFFER, vbo);
        const auto stride = static_cast<GLsizei>(sizeof(MeshVertex));
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, offset(offsetof(MeshVertex, position)));
        glEnableVertexAttribArray(1);
        glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, offset(offsetof(MeshVertex, normal)));
        glEnableVertexAttribArray(2);
        glVertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, stride, offset(offsetof(MeshVertex, colour)));
        glEnableVertexAttribArray(3);
        glVertexAttribPointer(3, 1, GL_FLOAT, GL_FALSE, stride, offset(offsetof(MeshVertex, material)));
    };
    meshVao(tableVao_, tableVbo_);
    meshVao(cueVao_, cueVbo_);
    const std::vector<MeshVertex> cue = buildCueStickMesh();
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(cue.size() * sizeof(MeshVertex)), cue.data(), GL_STATIC_DRAW);
    cueCount_ = static_cast<int>(cue.size());

    // One quad, [-1, 1]^2 as a triangle strip: an impostor per ball and ghost ball, a shadow per ball.
    const std::array<float, 8> corners{-1, -1, 1, -1, -1, 1, 1, 1};
    glGenBuffers(1, &quadVbo_);
    glBindBuffer(GL_ARRAY_BUFFER, quadVbo_);
    glBufferData(GL_ARRAY_BUFFER, sizeof(corners), corners.data(), GL_STATIC_DRAW);
    auto ballVao = [this](unsigned int& vao, unsigned int& instances) {
        glGenVertexArrays(1, &vao);
        glBindVertexArray(vao);
        glBindBuffer(GL_ARRAY_BUFFER, quadVbo_);
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), offset(0));
        glGenBuffers(1, &instances);
        glBindBuffer(GL_ARRAY_BUFFER, instances);
        for (unsigned int k = 0; k < 4; ++k) {
            glEnableVertexAttribArray(1 + k);
            glVertexAttribPointer(1 + k, 4, GL_FLOAT, GL_FALSE, kFloatsPerBall * sizeof(float), offset(4 * k * sizeof(float)));
            glVertexAttribDivisor(1 + k, 1);
        }
    };
    ballVao(ballVao_, ballInstanceVbo_);
    ballVao(ghostVao_, ghostInstanceVbo_);

    // Shadows: the quad per ball, reading the centre and radius from the ball instances.
    glGenVertexArrays(1, &shadowVao_);
    glBindVertexArray(shadowVao_);
    glBindBuffer(GL_ARRAY_BUFFER, quadVbo_);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), offset(0));
    glBindBuffer(GL_ARRAY_BUFFER, ballInstanceVbo_);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, kFloatsPerBall * sizeof(float), offset(0));
    glVertexAttribDivisor(1, 1);

    for (LineBuffer* b : {&pathLines_, &markerLines_, &ghostLines_, &dynamicLines_}) createLineBuffer(*b);
    glBindVertexArray(0);
    createDigitTexture();
    initialized_ = true;
    tableDirty_ = overlaysDirty_ = true;
    return true;
}

void TableRenderer::release()
{
    if (!initialized_) return;
    for (unsigned int* vao : {&tableVao_, &cueVao_, &ballVao_, &ghostVao_, &shadowVao_, &pathLines_.vao, &markerLines_.vao,
                              &ghostLines_.vao, &dynamicLines_.vao}) {
        glDeleteVertexArrays(1, vao);
        *vao = 0;
    }
    for (unsigned int* vbo : {&tableVbo_, &cueVbo_, &ballInstanceVbo_, &ghostInstanceVbo_,
                              &quadVbo_, &pathLines_.vbo, &markerLines_.vbo, &ghostLines_.vbo, &dynamicLines_.vbo}) {
        glDeleteBuffers(1, vbo);
        *vbo = 0;
    }
    glDeleteTextures(1, &digitTexture_);
    digitTexture_ = 0;
    tableCache_.reset();
    tableMultisampled_.reset();
    cacheGeneration_ = -1;
    hasLastFrame_ = false;
    tableProgram_.reset();
    tableCutProgram_.reset();
    ballProgram_.reset();
    ghostProgram_.reset();
    shadowProgram_.reset();
    lineProgram_.reset();
    initialized_ = false;
}

void TableRenderer::createLineBuffer(LineBuffer& buffer)
{
    glGenVertexArrays(1, &buffer.vao);
    glGenBuffers(1, &buffer.vbo);
    glBindVertexArray(buffer.vao);
    glBindBuffer(GL_ARRAY_BUFFER, buffer.vbo);
    const auto stride = static_cast<GLsizei>(sizeof(LineVertex));
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, offset(offsetof(LineVertex, position)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, stride, offset(offsetof(LineVertex, colour)));
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, stride, offset(offsetof(LineVertex, time)));
    buffer.capacity = 0;
    buffer.count = 0;
}

void TableRenderer::uploadLines(LineBuffer& buffer, const std::vector<LineVertex>& vertices)
{
    glBindBuffer(GL_ARRAY_BUFFER, buffer.vbo);
    if (vertices.size() > buffer.capacity) {
        // Grow geometrically so that a growing frame-to-frame load settles quickly.
        buffer.capacity = std::max<std::size_t>(vertices.size(), 2 * buffer.capacity);
        glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(buffer.capacity * sizeof(LineVertex)), nullptr,
                     GL_DYNAMIC_DRAW);
    }
    if (!vertices.empty())
        glBufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(vertices.size() * sizeof(LineVertex)), vertices.data());
    buffer.count = static_cast<int>(vertices.size());
}

void TableRenderer::createDigitTexture()
{
    QImage atlas(4 * kDigitCell, 4 * kDigitCell, QImage::Format_ARGB32_Premultiplied);
    atlas.fill(Qt::black);
    QPainter painter(&atlas);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setRenderHint(QPainter::TextAntialiasing);
    QFont font(QStringLiteral("DejaVu Sans"));
    font.setBold(true);
    font.setPixelSize(static_cast<int>(kDigitCell * 0.62));
    painter.setFont(font);
    painter.setPen(Qt::white);
    for (int n = 1; n < 16; ++n) {
        const QRect cell((n % 4) * kDigitCell, (n / 4) * kDigitCell, kDigitCell, kDigitCell);
        if (n >= 10) {
            QFont narrow = font;
            narrow.setPixelSize(static_cast<int>(kDigitCell * 0.52));
            narrow.setStretch(85);
            painter.setFont(narrow);
        } else {
            painter.setFont(font);
        }
        painter.drawText(cell, Qt::AlignCenter, QString::number(n));
        // 6 and 9 are underlined so that they can be told apart upside down.
        if (n == 6 || n == 9) painter.fillRect(QRect(cell.center().x() - 16, cell.bottom() - 22, 32, 7), Qt::white);
    }
    painter.end();
    const QImage grey = atlas.convertToFormat(QImage::Format_Grayscale8);
    glGenTextures(1, &digitTexture_);
    glBindTexture(GL_TEXTURE_2D, digitTexture_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    // Row 0 of the image becomes texture row v = 0 (ball.frag flips v to suit); the copy packs the
    // rows tightly whatever the image's line padding.
    std::vector<unsigned char> pixels(static_cast<std::size_t>(grey.width() * grey.height()));
    for (int y = 0; y < grey.height(); ++y)
        std::copy_n(grey.constScanLine(y), grey.width(), pixels.begin() + static_cast<std::ptrdiff_t>(y) * grey.width());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, grey.width(), grey.height(), 0, GL_RED, GL_UNSIGNED_BYTE, pixels.data());
    glGenerateMipmap(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D, 0);
}

void TableRenderer::setScene(const ViewScene& scene)
{
    const SimulationResult* before = scene_.result.get();
    const SimulationResult* after = scene.result.get();
    const bool sameTable = before && after && before->table.kind == after->table.kind &&
                           before->table.length == after->table.length && before->table.width == after->table.width &&
                           before->table.cushionHeight == after->table.cushionHeight &&
                           before->table.pockets.size() == after->table.pockets.size();
    if (!sameTable) tableDirty_ = true;
    // A cached image that holds the cue stick shows the old scene's cue ball and shot.
    if (cacheHasCue_) cacheGeneration_ = -1;
    scene_ = scene;
    overlaysDirty_ = true;
    orientations_.reset(scene_.result);
    looks_.clear();
    if (after)
        for (const Ball& b : after->balls) looks_.push_back(ballLook(after->table.kind, b.id));
}

void TableRenderer::uploadTable()
{
    std::vector<MeshVertex> mesh;
    if (scene_.result) {
        mesh = buildTableMesh(scene_.result->table);
        tableUncutCount_ = static_cast<int>(partitionByPocketCut(scene_.result->table, mesh));
    }
    glBindBuffer(GL_ARRAY_BUFFER, tableVbo_);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.size() * sizeof(MeshVertex)), mesh.data(), GL_STATIC_DRAW);
    tableCount_ = static_cast<int>(mesh.size());
    tableDirty_ = false;
    ++tableGeneration_;
}

void TableRenderer::uploadSceneOverlays(int highlightedEvent)
{
    std::vector<LineVertex> lines;
    std::vector<float> ghosts;
    if (scene_.result) {
        const SimulationResult& r = *scene_.result;
        buildPathLines(r, lines);
        uploadLines(pathLines_, lines);
        buildEventMarkers(r, highlightedEvent, lines);
        uploadLines(markerLines_, lines);
        buildGhostLines(r, lines);
        uploadLines(ghostLines_, lines);
        for (const GhostBall& g : ghostBalls(r)) {
            ghosts.insert(ghosts.end(), {g.centre.x(), g.centre.y(), g.centre.z(), g.radius, 0, 0, 0, 1, 0.92f, 0.92f, 0.95f,
                                         0, 0, 0, 0, 0.28f});
        }
    } else {
        for (LineBuffer* b : {&pathLines_, &markerLines_, &ghostLines_}) b->count = 0;
    }
    glBindBuffer(GL_ARRAY_BUFFER, ghostInstanceVbo_);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(ghosts.size() * sizeof(float)), ghosts.data(), GL_STATIC_DRAW);
    ghostCount_ = static_cast<int>(ghosts.size() / kFloatsPerBall);
    overlaysHighlight_ = highlightedEvent;
    overlaysDirty_ = false;
}

void TableRenderer::updateBallInstances(const RenderFrame& frame)
{
    states_.clear();
    scratchInstances_.clear();
    if (!scene_.result) {
        ballCount_ = 0;
        return;
    }
    const SimulationResult& r = *scene_.result;
    for (std::size_t i = 0; i < r.balls.size(); ++i) {
        const int index = static_cast<int>(i);
        states_.push_back(r.timelines.empty() ? r.balls[i].state : r.stateAt(index, frame.time));
        const BallState& s = states_.back();
        if (s.motion == MotionState::Pocketed) continue;
        const BallLook& look = looks_[i];
        const auto radius = static_cast<float>(r.balls[i].radius);
        float instance[kFloatsPerBall] = {static_cast<float>(s.position.x()), static_cast<float>(s.position.y()), radius, radius};
        putQuaternion(instance + 4, orientations_.at(index, frame.time));
        instance[8] = look.colour.x();
        instance[9] = look.colour.y();
        instance[10] = look.colour.z();
        instance[11] = static_cast<float>(look.number);
        instance[12] = look.striped ? 1.0f : 0.0f;
        instance[13] = look.dotted ? 1.0f : 0.0f;
        instance[14] = index == frame.selectedBall ? 1.0f : 0.0f;
        instance[15] = 1.0f;
        scratchInstances_.insert(scratchInstances_.end(), instance, instance + kFloatsPerBall);
    }
    glBindBuffer(GL_ARRAY_BUFFER, ballInstanceVbo_);
    const std::size_t needed = scratchInstances_.size() / kFloatsPerBall;
    if (needed > ballCapacity_) {
        ballCapacity_ = std::max<std::size_t>(needed, 2 * ballCapacity_);
        glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(ballCapacity_ * kFloatsPerBall * sizeof(float)), nullptr,
                     GL_DYNAMIC_DRAW);
    }
    if (needed > 0)
        glBufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(scratchInstances_.size() * sizeof(float)),
                        scratchInstances_.data());
    ballCount_ = static_cast<int>(needed);
}

void TableRenderer::drawLines(const LineBuffer& buffer, float widthPx, float pastAlpha,
                              float futureAlpha, float dashPeriod)
{
    if (buffer.count == 0 || (pastAlpha <= 0.0f && futureAlpha <= 0.0f)) return;
    lineProgram_->setUniformValue("uWidth", widthPx);
    lineProgram_->setUniformValue("uPastAlpha", pastAlpha);
    lineProgram_->setUniformValue("uFutureAlpha", futureAlpha);
    lineProgram_->setUniformValue("uDashPeriod", dashPeriod);
    glBindVertexArray(buffer.vao);
    glDrawArrays(GL_LINES, 0, buffer.count);
}

bool TableRenderer::tableCacheValid(const RenderFrame& frame, int samples, bool withCue) const
{
    return tableCache_ && tableCache_->isValid() && cacheGeneration_ == tableGeneration_ && cacheSamples_ == samples &&
           cacheHasCue_ == withCue && tableCache_->size() == frame.viewportPixels &&
           cacheViewProjection_ == frame.viewProjection;
}

// Draws the table (and the cue) into the cache. A multisampled target gets a cache with its own
// samples; a single-sampled one (the view's, whose balls and lines antialias themselves) gets the
// table drawn 4x multisampled and resolved once, so that its edges stay smooth at the cost of one
// single-sampled copy per frame.
void TableRenderer::buildTableCache(const RenderFrame& frame, int samples, bool withCue, unsigned int target)
{
    auto makeFbo = [&frame](int fboSamples) {
        QOpenGLFramebufferObjectFormat format;
        format.setAttachment(QOpenGLFramebufferObject::CombinedDepthStencil);  // as QOpenGLWidget's
        format.setSamples(fboSamples);
        return std::make_unique<QOpenGLFramebufferObject>(frame.viewportPixels, format);
    };
    if (!tableCache_ || tableCache_->size() != frame.viewportPixels || cacheSamples_ != samples) {
        tableCache_ = makeFbo(samples);
        cacheSamples_ = samples;
    }
    const bool resolve = samples == 0;
    if (resolve && (!tableMultisampled_ || tableMultisampled_->size() != frame.viewportPixels))
        tableMultisampled_ = makeFbo(kTableSamples);
    if (!resolve) tableMultisampled_.reset();
    cacheGeneration_ = -1;
    QOpenGLFramebufferObject* drawInto = resolve ? tableMultisampled_.get() : tableCache_.get();
    if (!tableCache_->isValid() || !drawInto->isValid()) return;
    glBindFramebuffer(GL_FRAMEBUFFER, drawInto->handle());
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    drawTable(frame);
    if (withCue) drawCue(frame);
    if (resolve) {
        const int w = frame.viewportPixels.width(), h = frame.viewportPixels.height();
        glBindFramebuffer(GL_READ_FRAMEBUFFER, tableMultisampled_->handle());
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, tableCache_->handle());
        glBlitFramebuffer(0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    cacheViewProjection_ = frame.viewProjection;
    cacheGeneration_ = tableGeneration_;
    cacheHasCue_ = withCue;
}

void TableRenderer::drawCue(const RenderFrame& frame)
{
    const SimulationResult& r = *scene_.result;
    const std::optional<QMatrix4x4> model = cuePlacement(r, *scene_.shot);
    if (!model) return;
    const std::array<QVector3D, 2> lamps = lampPositions(r.table);
    tableProgram_->bind();
    tableProgram_->setUniformValue("uViewProjection", frame.viewProjection);
    tableProgram_->setUniformValue("uEye", frame.eye);
    tableProgram_->setUniformValueArray("uLights", lamps.data(), 2);
    tableProgram_->setUniformValue("uModel", *model);
    glBindVertexArray(cueVao_);
    glDrawArrays(GL_TRIANGLES, 0, cueCount_);
}

// The table: the part no pocket reaches without the pocket cut, the rest with it.
void TableRenderer::drawTable(const RenderFrame& frame)
{
    const SimulationResult& r = *scene_.result;
    const auto L = static_cast<float>(r.table.length), W = static_cast<float>(r.table.width);
    const std::array<QVector3D, 2> lamps = lampPositions(r.table);
    std::array<QVector3D, 6> pockets{};
    const int pocketCount = r.table.pockets.size() == 6 ? 6 : 0;
    // The pockets by place (table.frag looks up one by the fragment's sixth of the table): bottom
    // left, middle, right, then the top row; each slot takes the pocket nearest to its place.
    for (int slot = 0; slot < pocketCount; ++slot) {
        const Vec2 place(r.table.length * (slot % 3) / 2.0, r.table.width * (slot / 3));
        const Pocket* nearest = &r.table.pockets.front();
        for (const Pocket& p : r.table.pockets)
            if ((p.centre - place).norm() < (nearest->centre - place).norm()) nearest = &p;
        pockets[static_cast<std::size_t>(slot)] = QVector3D(static_cast<float>(nearest->centre.x()),
                                                            static_cast<float>(nearest->centre.y()),
                                                            static_cast<float>(nearest->radius));
    }
    glBindVertexArray(tableVao_);
    for (QOpenGLShaderProgram* program : {tableCutProgram_.get(), tableProgram_.get()}) {
        program->bind();
        program->setUniformValue("uViewProjection", frame.viewProjection);
        program->setUniformValue("uModel", QMatrix4x4());
        program->setUniformValue("uEye", frame.eye);
        program->setUniformValueArray("uLights", lamps.data(), 2);
        program->setUniformValueArray("uPockets", pockets.data(), 6);
        program->setUniformValue("uPocketCount", pocketCount);
        program->setUniformValue("uTableSize", QVector2D(L, W));
        if (program == tableCutProgram_.get()) glDrawArrays(GL_TRIANGLES, tableUncutCount_, tableCount_ - tableUncutCount_);
        else glDrawArrays(GL_TRIANGLES, 0, tableUncutCount_);
    }
}

void TableRenderer::render(const RenderFrame& frame)
{
    glViewport(0, 0, frame.viewportPixels.width(), frame.viewportPixels.height());
    glClearColor(0.11f, 0.12f, 0.14f, 1.0f);
    glDisable(GL_SCISSOR_TEST);  // QPainter may leave it on in a widget
    glDisable(GL_STENCIL_TEST);
    tableUncached_ = false;
    if (!initialized_ || !scene_.result) {
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        return;
    }
    const SimulationResult& r = *scene_.result;
    if (tableDirty_) uploadTable();
    if (overlaysDirty_ || overlaysHighlight_ != frame.highlightedEvent) uploadSceneOverlays(frame.highlightedEvent);
    updateBallInstances(frame);

    const std::array<QVector3D, 2> lamps = lampPositions(r.table);

    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);

    // The table (and the cue before the shot), from the cache when the camera has not moved since
    // the last frame; drawn straight into the frame, without antialiasing, while the camera moves.
    GLint target = 0, samples = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &target);
    glGetIntegerv(GL_SAMPLES, &samples);
    const bool beforeShot = frame.time <= 0.0;
    const bool showCue = beforeShot && scene_.shot && frame.overlays.test(static_cast<std::size_t>(Overlay::CueAndAim));
    const bool moving = hasLastFrame_ && lastViewProjection_ != frame.viewProjection;
    lastViewProjection_ = frame.viewProjection;
    hasLastFrame_ = true;
    if (!moving && !tableCacheValid(frame, samples, showCue)) buildTableCache(frame, samples, showCue, static_cast<GLuint>(target));
    const bool cached = tableCacheValid(frame, samples, showCue);
    tableUncached_ = moving && !cached;  // not when the cache failed: that would repaint for ever
    if (cached) {
        const int w = frame.viewportPixels.width(), h = frame.viewportPixels.height();
        glBindFramebuffer(GL_READ_FRAMEBUFFER, tableCache_->handle());
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(target));
        glBlitFramebuffer(0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT, GL_NEAREST);
        glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(target));
    } else {
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        drawTable(frame);
        if (showCue) drawCue(frame);
    }

    // Contact shadows, then the balls.
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
    if (ballCount_ > 0) {
        shadowProgram_->bind();
        shadowProgram_->setUniformValue("uViewProjection", frame.viewProjection);
        glBindVertexArray(shadowVao_);
        glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, ballCount_);
    }
    // Balls blend only their antialiased rim; they still write depth.
    glDepthMask(GL_TRUE);
    auto bindBallProgram = [&frame, &lamps](QOpenGLShaderProgram& program) {
        program.bind();
        program.setUniformValue("uViewProjection", frame.viewProjection);
        program.setUniformValue("uEye", frame.eye);
        program.setUniformValue("uCameraUp", frame.cameraUp);
        program.setUniformValue("uPixelAngle", frame.pixelAngle);
        program.setUniformValueArray("uLights", lamps.data(), 2);
        program.setUniformValue("uDigits", 0);
    };
    bindBallProgram(*ballProgram_);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, digitTexture_);
    if (ballCount_ > 0) {
        glBindVertexArray(ballVao_);
        glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, ballCount_);
    }

    // Overlays: translucent, depth-tested against the table and the balls, not writing depth.
    glDepthMask(GL_FALSE);
    auto on = [&frame](Overlay o) { return frame.overlays.test(static_cast<std::size_t>(o)); };
    if (on(Overlay::GhostBalls) && ghostCount_ > 0) {
        bindBallProgram(*ghostProgram_);
        glBindVertexArray(ghostVao_);
        glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, ghostCount_);
    }

    scratchLines_.clear();
    if (on(Overlay::Velocities)) appendVelocityArrows(r, states_, scratchLines_);
    if (on(Overlay::Spin)) appendSpinIndicators(r, states_, scratchLines_);
    if (showCue) appendAimLine(r, *scene_.shot, scratchLines_);
    appendSelectionRing(r, states_, frame.selectedBall, scratchLines_);
    uploadLines(dynamicLines_, scratchLines_);

    lineProgram_->bind();
    lineProgram_->setUniformValue("uViewProjection", frame.viewProjection);
    lineProgram_->setUniformValue("uViewport", QVector2D(static_cast<float>(frame.viewportPixels.width()),
                                                         static_cast<float>(frame.viewportPixels.height())));
    lineProgram_->setUniformValue("uTime", static_cast<float>(frame.time));
    drawLines(pathLines_, 2.5f, on(Overlay::Trails) ? 1.0f : 0.0f, on(Overlay::FuturePaths) ? 0.75f : 0.0f, 0.035f);
    if (on(Overlay::GhostBalls)) drawLines(ghostLines_, 2.0f, 1.0f, 0.5f, 0.0f);
    if (on(Overlay::EventMarkers)) drawLines(markerLines_, 2.5f, 1.0f, 0.45f, 0.0f);
    drawLines(dynamicLines_, 3.0f, 1.0f, 1.0f, 0.0f);

    glBindVertexArray(0);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
}

}  // namespace cuelab
