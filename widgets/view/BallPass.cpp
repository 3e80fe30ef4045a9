#include "BallPass.h"

#include <QImage>
#include <QOpenGLShaderProgram>
#include <QPainter>

#include <array>

namespace cuelab {

namespace {

constexpr int kDigitCell = 128;  // pixels per digit cell of the 4 x 4 atlas

const void* offset(std::size_t bytes) { return reinterpret_cast<const void*>(bytes); }

}  // namespace

void BallPass::create()
{
    QOpenGLExtraFunctions* gl = currentGl();
    if (!gl) return;
    // One quad, [-1, 1]^2 as a triangle strip: an impostor per ball and ghost ball, a shadow per ball.
    const std::array<float, 8> corners{-1, -1, 1, -1, -1, 1, 1, 1};
    gl->glBindBuffer(GL_ARRAY_BUFFER, quad_.create());
    gl->glBufferData(GL_ARRAY_BUFFER, sizeof(corners), corners.data(), GL_STATIC_DRAW);
    balls_.create(quad_.id());
    // Shadows: the quad per ball, reading the centre and radius from the ball instances.
    gl->glBindVertexArray(shadowVao_.create());
    gl->glBindBuffer(GL_ARRAY_BUFFER, quad_.id());
    gl->glEnableVertexAttribArray(0);
    gl->glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), offset(0));
    gl->glBindBuffer(GL_ARRAY_BUFFER, balls_.instanceBuffer());
    gl->glEnableVertexAttribArray(1);
    gl->glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, kFloatsPerBall * sizeof(float), offset(0));
    gl->glVertexAttribDivisor(1, 1);
    gl->glBindVertexArray(0);
    createDigitTexture();
}

void BallPass::reset()
{
    balls_.reset();
    shadowVao_.reset();
    quad_.reset();
    digits_.reset();
}

void BallPass::setScene(const ViewScene& scene)
{
    result_ = scene.result;
    orientations_.reset(result_);
    looks_.clear();
    if (result_)
        for (const Ball& b : result_->balls) looks_.push_back(ballLook(result_->table.kind, b.id));
}

void BallPass::update(const RenderFrame& frame)
{
    states_.clear();
    instances_.clear();
    if (result_) {
        const SimulationResult& r = *result_;
        for (std::size_t i = 0; i < r.balls.size(); ++i) {
            const int index = static_cast<int>(i);
            states_.push_back(r.timelines.empty() ? r.balls[i].state : r.stateAt(index, frame.time));
            const BallState& s = states_.back();
            if (isOutOfPlay(s.motion)) continue;
            const BallLook& look = looks_[i];
            const auto radius = static_cast<float>(r.balls[i].radius);
            const Eigen::Quaterniond q = orientations_.at(index, frame.time);
            const float quaternion[4] = {static_cast<float>(q.x()), static_cast<float>(q.y()), static_cast<float>(q.z()),
                                         static_cast<float>(q.w())};
            appendBallInstance(instances_,
                               // (a flying ball above its resting height: its shadow stays on the cloth)
                               QVector3D(static_cast<float>(s.position.x()), static_cast<float>(s.position.y()),
                                         radius + static_cast<float>(s.z)),
                               radius, quaternion, look.colour, look.number, look.striped, look.dotted,
                               index == frame.selectedBall, 1.0f);
        }
    }
    balls_.upload(instances_);
}

void BallPass::drawShadows(const RenderFrame& frame, ShaderLibrary& shaders)
{
    if (balls_.count() == 0) return;
    shaders.shadow->bind();
    shaders.shadow->setUniformValue("uViewProjection", frame.viewProjection);
    QOpenGLExtraFunctions* gl = currentGl();
    gl->glBindVertexArray(shadowVao_.id());
    gl->glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, balls_.count());
}

void BallPass::drawBalls(const RenderFrame& frame, ShaderLibrary& shaders, const std::array<QVector3D, 2>& lamps)
{
    bindBallProgram(*shaders.ball, frame, lamps);
    QOpenGLExtraFunctions* gl = currentGl();
    gl->glActiveTexture(GL_TEXTURE0);
    gl->glBindTexture(GL_TEXTURE_2D, digits_.id());
    balls_.draw();
}

void BallPass::createDigitTexture()
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
    QOpenGLExtraFunctions* gl = currentGl();
    gl->glBindTexture(GL_TEXTURE_2D, digits_.create());
    gl->glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    // Row 0 of the image becomes texture row v = 0 (ball.frag flips v to suit); the copy packs the
    // rows tightly whatever the image's line padding.
    std::vector<unsigned char> pixels(static_cast<std::size_t>(grey.width() * grey.height()));
    for (int y = 0; y < grey.height(); ++y)
        std::copy_n(grey.constScanLine(y), grey.width(), pixels.begin() + static_cast<std::ptrdiff_t>(y) * grey.width());
    gl->glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, grey.width(), grey.height(), 0, GL_RED, GL_UNSIGNED_BYTE, pixels.data());
    gl->glGenerateMipmap(GL_TEXTURE_2D);
    gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    gl->glBindTexture(GL_TEXTURE_2D, 0);
}

}  // namespace cuelab
