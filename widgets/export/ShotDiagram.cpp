#include "ShotDiagram.h"

#include "i18n/UiNumbers.h"
#include "editor/RunState.h"

#include "Curves.h"
#include "ShotOutcome.h"
#include "outcome/OutcomeLine.h"
#include "view/BallAppearance.h"

#include <QCoreApplication>
#include <QFontMetricsF>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>
#include <utility>

namespace cuelab {

namespace {

constexpr double kMargin = 20.0;      // canvas units around the table's frame
constexpr double kRailWidth = 0.10;   // m, the wooden frame drawn around the playing surface
constexpr double kCaptionGap = 16.0;  // canvas units between the frame and the caption
constexpr double kMarkerSize = 5.0;   // canvas units, half the diagonal of a contact marker
constexpr double kFactPx = 13.0;      // canvas units, the facts table's text
constexpr double kFactRow = 18.0;     // canvas units, one row of the facts table

// Every tr() call of this file is in a member of ShotDiagram: lupdate gives them its context.
QString tr(const char* text) { return QCoreApplication::translate("cuelab::ShotDiagram", text); }

QColor fromLinear(const QVector3D& c)
{
    auto g = [](float v) { return std::pow(std::clamp(static_cast<double>(v), 0.0, 1.0), 1.0 / 2.2); };
    return QColor::fromRgbF(static_cast<float>(g(c.x())), static_cast<float>(g(c.y())), static_cast<float>(g(c.z())));
}

QFont pixelFont(double size, bool bold = false)
{
    QFont f(QStringLiteral("DejaVu Sans"));
    f.setPixelSize(std::max(1, static_cast<int>(std::lround(size))));
    f.setBold(bold);
    return f;
}

QString seconds(double t) { return uiNumber(t, 3) + QStringLiteral(" s"); }

// A diamond (contact marker) or a triangle (pocketing) as a polygon: not a circle.
QPolygonF diamond(const QPointF& c, double r)
{
    return QPolygonF({c + QPointF(0, -r), c + QPointF(r, 0), c + QPointF(0, r), c + QPointF(-r, 0)});
}

void arrowHead(QPainter& p, const QPointF& tip, const QPointF& direction, double size)
{
    const double len = std::hypot(direction.x(), direction.y());
    if (len <= 0.0) return;
    const QPointF d = direction / len;
    const QPointF n(-d.y(), d.x());
    p.drawPolygon(QPolygonF({tip, tip - size * d + 0.5 * size * n, tip - size * d - 0.5 * size * n}));
}

}  // namespace

ShotDiagram::ShotDiagram(std::shared_ptr<const SimulationResult> result, DiagramText text, double time, DiagramStyle style)
    : result_(std::move(result)), text_(std::move(text)), style_(style)
{
    const double end = result_ ? result_->endTime : 0.0;
    time_ = time < 0.0 ? end : std::min(time, end);
}

QTransform ShotDiagram::tableToCanvas() const
{
    const double L = result_->table.length;
    const double W = result_->table.width;
    const double s = (kCanvasWidth - 2 * kMargin) / (L + 2 * kRailWidth);
    // x right, y up on the table: flip y so that the top rail (y = W) is at the top of the canvas.
    const double x0 = kMargin + kRailWidth * s;
    const double y0 = kMargin + kRailWidth * s + W * s;
    return QTransform(s, 0, 0, -s, x0, y0);
}

QRectF ShotDiagram::tableRect() const
{
    const QTransform m = tableToCanvas();
    return QRectF(m.map(QPointF(0, result_->table.width)), m.map(QPointF(result_->table.length, 0)));
}

double ShotDiagram::canvasHeight() const
{
    const QTransform m = tableToCanvas();
    const double frameBottom = tableRect().bottom() + kRailWidth * m.m11() + kMargin;
    return frameBottom + (style_.caption ? captionHeight() + kCaptionGap : 0.0);
}

QString ShotDiagram::captionText() const
{
    QString text;
    const ShotOutcome outcome = shotOutcome(*result_);
    text += tr("Outcome: %1").arg(outcomeLine(*result_, outcome)) + QLatin1Char('\n');
    // A partial run (still going, cancelled, cut short) says so first (issue 39).
    if (const QString unfinished = RunState::unfinishedNote(*result_); !unfinished.isEmpty()) text.prepend(unfinished + QLatin1Char('\n'));
    const bool atEnd = time_ >= result_->endTime && result_->finished();
    text += atEnd ? tr("Balls where they rest (t = %1). ").arg(seconds(time_))
                  : tr("Balls at t = %1 of %2; paths dashed after it. ").arg(seconds(time_), seconds(result_->endTime));
    text += tr("Dashed rings: start positions. \u25C6 blue: ball-ball contact, \u25C6 red: cushion, \u25B2 pocketed.");
    return text;
}

double ShotDiagram::captionHeight() const
{
    const double width = kCanvasWidth - 2 * kMargin;
    double h = 0.0;
    if (!text_.title.isEmpty()) h += QFontMetricsF(pixelFont(22, true)).height() + 6;
    h += QFontMetricsF(pixelFont(14)).boundingRect(QRectF(0, 0, width, 1e6), Qt::TextWordWrap, captionText()).height() + 8;
    h += factsHeight();
    if (!text_.notes.isEmpty())
        h += QFontMetricsF(pixelFont(14)).boundingRect(QRectF(0, 0, width, 1e6), Qt::TextWordWrap, text_.notes).height() + 4;
    return h;
}

// The shot on the left, the physics on the right, one fact a row (name in grey, value in black).
double ShotDiagram::factsHeight() const
{
    const qsizetype rows = std::max(text_.facts.shot.size(), text_.facts.physics.size());
    return rows > 0 ? static_cast<double>(rows + 1) * kFactRow + 8 : 0.0;
}

void ShotDiagram::paintFacts(QPainter& p, double y) const
{
    const double width = kCanvasWidth - 2 * kMargin;
    const double column = (width - 20) / 2;
    const auto table = [&](double x, const QString& heading, const QList<Fact>& facts) {
        p.setFont(pixelFont(kFactPx, true));
        p.setPen(Qt::black);
        p.drawText(QRectF(x, y, column, kFactRow), Qt::AlignLeft | Qt::AlignVCenter, heading);
        double row = y + kFactRow;
        p.setFont(pixelFont(kFactPx));
        const QFontMetricsF metrics(p.font());
        for (const Fact& f : facts) {
            p.setPen(QColor(90, 90, 90));
            p.drawText(QRectF(x, row, column * 0.4, kFactRow), Qt::AlignLeft | Qt::AlignVCenter,
                       metrics.elidedText(f.name, Qt::ElideRight, column * 0.4 - 4));
            p.setPen(Qt::black);
            p.drawText(QRectF(x + column * 0.4, row, column * 0.6, kFactRow), Qt::AlignLeft | Qt::AlignVCenter,
                       metrics.elidedText(f.value, Qt::ElideRight, column * 0.6));
            row += kFactRow;
        }
    };
    if (!text_.facts.shot.isEmpty()) table(kMargin, tr("The shot"), text_.facts.shot);
    if (!text_.facts.physics.isEmpty()) table(kMargin + column + 20, tr("The physics"), text_.facts.physics);
}

QColor ShotDiagram::ballColour(int ball) const
{
    return fromLinear(ballLook(result_->table.kind, result_->balls.at(static_cast<std::size_t>(ball)).id).colour);
}

QColor ShotDiagram::pathColour(int ball) const
{
    const BallLook look = ballLook(result_->table.kind, result_->balls.at(static_cast<std::size_t>(ball)).id);
    if (style_.cloth) return displayColour(cuelab::pathColour(look, result_->table.kind));
    // On paper a white or yellow line disappears: darken light colours.
    QColor c = displayColour(look.colour);
    if (c.lightnessF() > 0.6) c = c.darker(c.saturationF() < 0.2 ? 300 : 160);
    return c;
}

void ShotDiagram::paint(QPainter& painter, const QRectF& target) const
{
    if (!result_) return;
    const double h = canvasHeight();
    const double scale = std::min(target.width() / kCanvasWidth, target.height() / h);
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setRenderHint(QPainter::TextAntialiasing);
    painter.translate(target.left() + (target.width() - scale * kCanvasWidth) / 2,
                      target.top() + (target.height() - scale * h) / 2);
    painter.scale(scale, scale);
    paintCanvas(painter);
    painter.restore();
}

void ShotDiagram::paintCanvas(QPainter& p) const
{
    const QTransform m = tableToCanvas();
    p.fillRect(QRectF(0, 0, kCanvasWidth, canvasHeight()), Qt::white);
    paintTable(p, m);
    paintPaths(p, m);
    paintMarkers(p, m);
    paintBalls(p, m);
    if (style_.caption) paintCaption(p);
}

void ShotDiagram::paintTable(QPainter& p, const QTransform& m) const
{
    const Table& table = result_->table;
    const QRectF surface = tableRect();
    const double rail = kRailWidth * m.m11();
    const QRectF frame = surface.adjusted(-rail, -rail, rail, rail);

    const QColor wood = style_.cloth ? QColor(92, 54, 28) : QColor(232, 232, 232);
    const QColor cloth = style_.cloth ? QColor(20, 110, 62) : Qt::white;
    p.setPen(QPen(style_.cloth ? QColor(60, 34, 16) : QColor(120, 120, 120), 1.2));
    p.setBrush(wood);
    p.drawRoundedRect(frame, rail * 0.3, rail * 0.3);
    p.setPen(Qt::NoPen);
    p.setBrush(cloth);
    p.drawRect(surface);

    // Sights (diamonds) on the rails: eighths of the length, quarters of the width (pool, carom).
    if (table.kind != TableKind::Snooker) {
        p.setBrush(style_.cloth ? QColor(235, 225, 200) : QColor(150, 150, 150));
        const double r = rail * 0.12;
        for (int i = 1; i < 8; ++i) {
            if (i == 4 && table.hasPockets()) continue;
            const double x = surface.left() + surface.width() * i / 8.0;
            p.drawPolygon(diamond(QPointF(x, frame.top() + rail / 2), r));
            p.drawPolygon(diamond(QPointF(x, frame.bottom() - rail / 2), r));
        }
        for (int i = 1; i < 4; ++i) {
            const double y = surface.top() + surface.height() * i / 4.0;
            p.drawPolygon(diamond(QPointF(frame.left() + rail / 2, y), r));
            p.drawPolygon(diamond(QPointF(frame.right() - rail / 2, y), r));
        }
    }

    // Pockets as dark holes (paths, not circles), then the cushion noses and jaw tips on top.
    p.setBrush(style_.cloth ? QColor(15, 15, 15) : QColor(70, 70, 70));
    for (const Pocket& pocket : table.pockets) {
        QPainterPath hole;
        const double r = pocket.radius * m.m11();
        hole.addEllipse(m.map(QPointF(pocket.centre.x(), pocket.centre.y())), r, r);
        p.drawPath(hole);
    }
    p.setPen(QPen(style_.cloth ? QColor(10, 70, 36) : QColor(40, 40, 40), 1.6, Qt::SolidLine, Qt::RoundCap));
    for (const CushionSegment& c : table.cushions)
        p.drawLine(m.map(QPointF(c.a.x(), c.a.y())), m.map(QPointF(c.b.x(), c.b.y())));
    p.setBrush(Qt::NoBrush);
    for (const JawTip& jaw : table.jaws) {
        QPainterPath tip;
        const double r = jaw.radius * m.m11();
        tip.addEllipse(m.map(QPointF(jaw.centre.x(), jaw.centre.y())), r, r);
        p.drawPath(tip);
    }
}

void ShotDiagram::paintPaths(QPainter& p, const QTransform& m) const
{
    plots::SamplingOptions options;
    options.samplesPerPiece = 16;
    options.maxStep = std::max(result_->endTime, 1e-3) / 400.0;
    for (int b = 0; b < static_cast<int>(result_->balls.size()); ++b) {
        const QColor colour = pathColour(b);
        QPen solid(colour, 1.8, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin);
        QPen dashed(colour, 1.4, Qt::DashLine, Qt::RoundCap, Qt::RoundJoin);
        for (const plots::Piece& piece : plots::sampleBall(*result_, b, options)) {
            QPolygonF before;
            QPolygonF after;
            double length = 0.0;
            for (const plots::Sample& s : piece.samples) {
                const QPointF q = m.map(QPointF(s.state.position.x(), s.state.position.y()));
                QPolygonF& line = s.time <= time_ ? before : after;
                if (line.isEmpty() && &line == &after && !before.isEmpty()) line << before.back();
                if (!line.isEmpty()) length += std::hypot(q.x() - line.back().x(), q.y() - line.back().y());
                line << q;
            }
            if (length < 1.0) continue;  // a ball at rest or barely moving
            p.setBrush(Qt::NoBrush);
            p.setPen(solid);
            if (before.size() > 1) p.drawPolyline(before);
            p.setPen(dashed);
            if (after.size() > 1) p.drawPolyline(after);
            if (length < 36.0) continue;
            // An arrow half way along the piece, pointing the way the ball runs.
            QPolygonF all = before;
            for (int i = before.isEmpty() ? 0 : 1; i < after.size(); ++i) all << after[i];
            double run = 0.0;
            for (int i = 1; i < all.size(); ++i) {
                const QPointF d = all[i] - all[i - 1];
                run += std::hypot(d.x(), d.y());
                if (run >= length / 2) {
                    p.setPen(Qt::NoPen);
                    p.setBrush(colour);
                    arrowHead(p, all[i], d, 9.0);
                    break;
                }
            }
        }
    }
}

void ShotDiagram::paintMarkers(QPainter& p, const QTransform& m) const
{
    const ShotOutcome outcome = shotOutcome(*result_);
    int collisions = 0;
    for (const Event& e : result_->events)
        if (isCollision(e.kind) || e.kind == EventKind::BallPocket) ++collisions;
    // Many contacts (a break): label only the struck ball's, so that the times stay readable.
    const bool labelAll = collisions <= 30;
    std::vector<QPointF> labelled;
    p.setFont(pixelFont(11));
    const QColor ballBall(30, 70, 170);
    const QColor cushion(190, 40, 30);
    for (const Event& e : result_->events) {
        QPointF at;
        QColor colour;
        bool pocket = false;
        if (isCollision(e.kind)) {
            at = m.map(QPointF(e.contactPoint.x(), e.contactPoint.y()));
            colour = e.kind == EventKind::BallBall ? ballBall : cushion;
        } else if (e.kind == EventKind::BallPocket) {
            at = m.map(QPointF(e.before[0].position.x(), e.before[0].position.y()));
            colour = QColor(20, 20, 20);
            pocket = true;
        } else {
            continue;
        }
        p.setPen(QPen(Qt::white, 0.8));
        p.setBrush(colour);
        if (pocket)
            p.drawPolygon(QPolygonF({at + QPointF(0, -kMarkerSize * 1.2), at + QPointF(kMarkerSize, kMarkerSize * 0.8),
                                     at + QPointF(-kMarkerSize, kMarkerSize * 0.8)}));
        else
            p.drawPolygon(diamond(at, kMarkerSize));
        if (!style_.eventTimes || e.time > time_) continue;
        const bool own = e.balls[0] == outcome.struckBall || e.balls[1] == outcome.struckBall;
        if (!labelAll && !own && !pocket) continue;
        bool crowded = false;
        for (const QPointF& q : labelled) crowded = crowded || std::hypot(q.x() - at.x(), q.y() - at.y()) < 14.0;
        if (crowded) continue;
        labelled.push_back(at);
        const QString label = seconds(e.time);
        const QRectF box = QFontMetricsF(p.font()).boundingRect(label).adjusted(-2, -1, 2, 1);
        // Beside the marker, towards the inside of the table.
        const QPointF centre = tableRect().center();
        const double dx = at.x() < centre.x() ? 8.0 : -8.0 - box.width();
        const double dy = at.y() < centre.y() ? 14.0 : -6.0;
        const QRectF placed = box.translated(at + QPointF(dx, dy) - box.bottomLeft() + QPointF(0, box.height()));
        p.setPen(Qt::NoPen);
        p.setBrush(style_.cloth ? QColor(255, 255, 255, 200) : QColor(255, 255, 255, 220));
        p.drawRect(placed);
        p.setPen(colour.darker(130));
        p.drawText(placed, Qt::AlignCenter, label);
    }
}

void ShotDiagram::paintBalls(QPainter& p, const QTransform& m) const
{
    for (int b = 0; b < static_cast<int>(result_->balls.size()); ++b) {
        const Ball& ball = result_->balls[static_cast<std::size_t>(b)];
        const double r = ball.radius * m.m11();
        // Where it started, when it moved: a dashed ring (a path, so that only balls are circles).
        const BallState now = result_->stateAt(b, time_);
        const Vec2 start = ball.state.position;
        if (now.motion == MotionState::Pocketed || (now.position - start).norm() > 1e-3) {
            QPainterPath ring;
            ring.addEllipse(m.map(QPointF(start.x(), start.y())), r, r);
            p.setPen(QPen(pathColour(b), 1.0, Qt::DashLine));
            p.setBrush(Qt::NoBrush);
            p.drawPath(ring);
        }
        // A pocketed ball is not on the table: its label stands at its start, so every ball is named.
        if (now.motion == MotionState::Pocketed) {
            const BallLook look = ballLook(result_->table.kind, ball.id);
            const QString label = look.number > 0 ? QString::number(look.number) : QString::fromStdString(ball.id);
            p.setFont(pixelFont(12, true));
            const QPointF c = m.map(QPointF(start.x(), start.y()));
            const QRectF box = QFontMetricsF(p.font()).boundingRect(label).adjusted(-2, 0, 2, 0);
            const QRectF placed = box.translated(c + QPointF(r + 3, r + 3) - box.topLeft());
            p.setPen(Qt::NoPen);
            p.setBrush(QColor(255, 255, 255, 210));
            p.drawRect(placed);
            p.setPen(pathColour(b));
            p.drawText(placed, Qt::AlignCenter, label);
        }
    }
    for (int b = 0; b < static_cast<int>(result_->balls.size()); ++b) {
        const Ball& ball = result_->balls[static_cast<std::size_t>(b)];
        const BallState now = result_->stateAt(b, time_);
        if (now.motion == MotionState::Pocketed) continue;
        const double r = ball.radius * m.m11();
        const QPointF c = m.map(QPointF(now.position.x(), now.position.y()));
        const BallLook look = ballLook(result_->table.kind, ball.id);
        const QColor colour = ballColour(b);
        p.setPen(QPen(QColor(30, 30, 30), 1.0));
        p.setBrush(look.striped ? QColor(250, 250, 250) : colour);
        p.drawEllipse(c, r, r);
        if (look.striped) {  // the band: a clipped rectangle (a path)
            QPainterPath disc;
            disc.addEllipse(c, r - 0.5, r - 0.5);
            QPainterPath band;
            band.addRect(QRectF(c.x() - r, c.y() - 0.55 * r, 2 * r, 1.1 * r));
            p.setPen(Qt::NoPen);
            p.setBrush(colour);
            p.drawPath(disc.intersected(band));
        }
        // The number (pool) or the id (other balls), in a white disc or beside the ball.
        const QString label = look.number > 0 ? QString::number(look.number) : QString::fromStdString(ball.id);
        if (look.number > 0) {
            QPainterPath disc;
            disc.addEllipse(c, 0.55 * r, 0.55 * r);
            p.setPen(Qt::NoPen);
            p.setBrush(Qt::white);
            p.drawPath(disc);
            p.setPen(Qt::black);
            p.setFont(pixelFont(0.8 * r, true));
            p.drawText(QRectF(c.x() - r, c.y() - r, 2 * r, 2 * r), Qt::AlignCenter, label);
        } else {
            p.setFont(pixelFont(12, true));
            const QRectF box = QFontMetricsF(p.font()).boundingRect(label).adjusted(-2, 0, 2, 0);
            const QRectF placed = box.translated(c + QPointF(r + 3, r + 3) - box.topLeft());
            p.setPen(Qt::NoPen);
            p.setBrush(QColor(255, 255, 255, 210));
            p.drawRect(placed);
            p.setPen(Qt::black);
            p.drawText(placed, Qt::AlignCenter, label);
        }
    }
}

void ShotDiagram::paintCaption(QPainter& p) const
{
    const QTransform m = tableToCanvas();
    const double width = kCanvasWidth - 2 * kMargin;
    double y = tableRect().bottom() + kRailWidth * m.m11() + kMargin + kCaptionGap / 2;
    p.setPen(Qt::black);
    if (!text_.title.isEmpty()) {
        p.setFont(pixelFont(22, true));
        const double h = QFontMetricsF(p.font()).height();
        p.drawText(QRectF(kMargin, y, width, h), Qt::AlignLeft | Qt::AlignTop, text_.title);
        y += h + 6;
    }
    p.setFont(pixelFont(14));
    const QString caption = captionText();
    const QRectF box = QFontMetricsF(p.font()).boundingRect(QRectF(0, 0, width, 1e6), Qt::TextWordWrap, caption);
    p.drawText(QRectF(kMargin, y, width, box.height()), Qt::TextWordWrap, caption);
    y += box.height() + 8;
    paintFacts(p, y);
    y += factsHeight();
    if (!text_.notes.isEmpty()) {
        p.setPen(QColor(50, 50, 50));
        const QRectF notes = QFontMetricsF(p.font()).boundingRect(QRectF(0, 0, width, 1e6), Qt::TextWordWrap, text_.notes);
        p.drawText(QRectF(kMargin, y, width, notes.height()), Qt::TextWordWrap, text_.notes);
    }
}

}  // namespace cuelab
