#include "ConservationWidget.h"

#include "i18n/UiNumbers.h"

#include "Frames.h"

#include <QFontMetricsF>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace cuelab {

namespace {

const QColor kBodyColours[] = {QColor(40, 110, 220), QColor(230, 130, 20)};

void arrow(QPainter& p, const QPointF& from, const QPointF& to, const QColor& colour, Qt::PenStyle style = Qt::SolidLine)
{
    p.setPen(QPen(colour, 2.0, style, Qt::RoundCap));
    p.drawLine(from, to);
    const QPointF d = to - from;
    const double len = std::hypot(d.x(), d.y());
    if (len < 1.0) return;
    const QPointF u = d / len;
    const QPointF n(-u.y(), u.x());
    const double head = std::min(8.0, 0.4 * len);
    QPainterPath tip;
    tip.moveTo(to);
    tip.lineTo(to - head * u + 0.5 * head * n);
    tip.lineTo(to - head * u - 0.5 * head * n);
    tip.closeSubpath();
    p.setPen(Qt::NoPen);
    p.setBrush(colour);
    p.drawPath(tip);
    p.setBrush(Qt::NoBrush);
}

}  // namespace

ConservationWidget::ConservationWidget(QWidget* parent) : QWidget(parent)
{
    setMinimumSize(240, 200);
    setToolTip(tr("Left: each ball's momentum m·v (N s) drawn tip to tail, before and after, with their total "
                  "(dashed); in the centre-of-mass frame the chain closes on itself. Right: kinetic energy (J) "
                  "before and after, translation (solid) and rotation (light), and what was lost (hatched): to "
                  "the collision, and to the cloth since each ball's previous event."));
}

ConservationWidget::Figure ConservationWidget::figureOf(const explain::Explanation* e, bool centreOfMass)
{
    Figure f;
    f.bodies = e ? e->bodies : std::vector<explain::Body>{};
    f.cushion = e && (e->kind == EventKind::BallCushion || e->kind == EventKind::BallJaw);
    f.cushionImpulse = e ? Vec2(e->impulse.head<2>()) : Vec2::Zero();
    // A frame of its own only for a pair: a single ball's centre of mass is the ball.
    f.centreOfMass = centreOfMass && f.bodies.size() == 2;
    if (f.centreOfMass) {
        std::vector<aim::FrameBody> frame;
        for (const explain::Body& b : f.bodies) frame.push_back({b.mass, b.before.velocity, b.after.velocity});
        f.frameVelocity = aim::centreOfMassFrame(frame).velocity;
    }
    if (e && e->kind != EventKind::CueStrike)
        for (const explain::Body& b : f.bodies) {
            const double before = b.translationBefore + b.rotationBefore, after = b.translationAfter + b.rotationAfter;
            f.lostToEvent += before - after;
            f.lostToCloth += b.energyAfterPrevious - before;
        }
    return f;
}

Vec2 ConservationWidget::Figure::momentum(std::size_t body, int phase) const
{
    const explain::Body& b = bodies[body];
    return (phase == 0 ? b.momentumBefore() : b.momentumAfter()) - b.mass * frameVelocity;
}

void ConservationWidget::setExplanation(const explain::Explanation* e)
{
    explanation_ = e ? std::optional<explain::Explanation>(*e) : std::nullopt;
    figure_ = figureOf(e, centreOfMass_);
    update();
}

void ConservationWidget::setCentreOfMassFrame(bool on)
{
    if (on == centreOfMass_) return;
    centreOfMass_ = on;
    figure_ = figureOf(explanation_ ? &*explanation_ : nullptr, on);
    update();
}

void ConservationWidget::paintFigure(QPainter& p, const QRectF& area, const explain::Explanation& e)
{
    // Print colours: black text, grey frames, white paper.
    const QPalette print(Qt::black, Qt::white, Qt::white, QColor(120, 120, 120), QColor(160, 160, 160), Qt::black, Qt::white,
                         Qt::white, Qt::white);
    p.save();
    p.fillRect(area, Qt::white);
    paintBoth(p, area, figureOf(&e), print, area.width() < kSideBySideWidth);
    p.restore();
}

void ConservationWidget::paintEvent(QPaintEvent*)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    p.fillRect(rect(), palette().base());
    if (figure_.bodies.empty()) {
        p.setPen(palette().color(QPalette::Disabled, QPalette::Text));
        p.drawText(rect(), Qt::AlignCenter | Qt::TextWordWrap, tr("Momenta and energy of the selected event"));
        return;
    }
    paintBoth(p, QRectF(rect()).adjusted(4, 4, -4, -4), figure_, palette(), stacked());
}

void ConservationWidget::paintBoth(QPainter& p, const QRectF& all, const Figure& f, const QPalette& palette, bool stacked)
{
    if (stacked) {
        // Narrow (a dock of a small window): momentum above, energy below, each the whole width.
        const double split = all.height() * 0.58;
        paintMomenta(p, QRectF(all.left(), all.top(), all.width(), split - 6), f, palette);
        paintEnergy(p, QRectF(all.left(), all.top() + split + 6, all.width(), all.height() - split - 6), f, palette);
    } else {
        const double split = all.width() * 0.6;
        paintMomenta(p, QRectF(all.left(), all.top(), split - 6, all.height()), f, palette);
        paintEnergy(p, QRectF(all.left() + split + 6, all.top(), all.width() - split - 6, all.height()), f, palette);
    }
}

QString ConservationWidget::energyChange(double before, double after)
{
    const double change = after - before;
    // Round to what matters: a change below a millionth of the energy (a rounding error of the
    // arithmetic, an elastic collision) is none.
    if (std::abs(change) <= 1e-6 * std::max(std::abs(before), std::abs(after)) || std::abs(change) < 1e-12)
        return tr("ΔE = 0 J (conserved)");
    if (before <= 0.0) return tr("ΔE = %1 J").arg(uiSignificant(change, 3));
    const double percent = 100.0 * change / before;
    return tr("ΔE = %1 J (%2 %)").arg(uiSignificant(change, 3)).arg(uiSignificant(percent, std::abs(percent) >= 1.0 ? 3 : 2));
}

void ConservationWidget::paintMomenta(QPainter& p, const QRectF& area, const Figure& f, const QPalette& palette)
{
    const QFontMetricsF metrics(p.font());
    const double line = metrics.height();
    p.setPen(palette.color(QPalette::Text));
    p.drawText(QRectF(area.left(), area.top(), area.width(), line), Qt::AlignLeft,
               metrics.elidedText(f.centreOfMass ? tr("Momentum, centre-of-mass frame (N s)") : tr("Momentum (N s)"),
                                  Qt::ElideRight, area.width()));
    // Below the panels: "before"/"after", |P|, then the key.
    const QRectF body = area.adjusted(0, line + 4, 0, -(3 * line + 6));
    // Two panels, before and after, one scale for both: the longest chain of arrows fits.
    double longest = 1e-9;
    Vec2 lo = Vec2::Zero(), hi = Vec2::Zero();
    for (int phase = 0; phase < 2; ++phase) {
        Vec2 tip = Vec2::Zero();
        for (std::size_t k = 0; k < f.bodies.size(); ++k) {
            tip += f.momentum(k, phase);
            lo = lo.cwiseMin(tip);
            hi = hi.cwiseMax(tip);
        }
        longest = std::max(longest, (hi - lo).maxCoeff());
    }
    const double panelW = body.width() / 2.0 - 6.0;
    const double scale = 0.8 * std::min(panelW, body.height()) / longest;  // px per N s
    for (int phase = 0; phase < 2; ++phase) {
        const QRectF panel(body.left() + phase * (panelW + 12.0), body.top(), panelW, body.height());
        p.setPen(QPen(palette.color(QPalette::Mid), 1.0));
        p.drawRect(panel);
        // Centre the chain's bounding box in the panel (y up on the table, down on screen).
        const Vec2 mid = 0.5 * (lo + hi);
        auto toScreen = [&](const Vec2& v) {
            return QPointF(panel.center().x() + (v.x() - mid.x()) * scale, panel.center().y() - (v.y() - mid.y()) * scale);
        };
        Vec2 tip = Vec2::Zero();
        for (std::size_t k = 0; k < f.bodies.size(); ++k) {
            const Vec2 pk = f.momentum(k, phase);
            arrow(p, toScreen(tip), toScreen(tip + pk), kBodyColours[k % 2]);
            tip += pk;
        }
        if (f.bodies.size() > 1) arrow(p, toScreen(Vec2::Zero()), toScreen(tip), palette.color(QPalette::Text), Qt::DashLine);
        if (phase == 1 && f.cushion) {
            // The cushion's impulse closes the triangle: p' = p + J.
            const Vec2 before = f.bodies[0].momentumBefore();
            arrow(p, toScreen(before), toScreen(before + f.cushionImpulse), QColor(200, 40, 160), Qt::DotLine);
            p.setPen(QColor(200, 40, 160));
            p.drawText(toScreen(before + 0.5 * f.cushionImpulse) + QPointF(4, 10), tr("J (cushion)"));
            arrow(p, toScreen(Vec2::Zero()), toScreen(before), QColor(150, 150, 150), Qt::DotLine);
        }
        p.setPen(palette.color(QPalette::Text));
        const QRectF under(panel.left() - 4, panel.bottom() + 2, panel.width() + 8, line);
        p.drawText(under, Qt::AlignCenter, phase == 0 ? tr("before") : tr("after"));
        // A total that is rounding only (the centre-of-mass frame's, about 1e-17 N s) reads 0.
        const double total = tip.norm() <= 1e-12 * std::max(longest, 1e-9) ? 0.0 : tip.norm();
        p.drawText(under.translated(0, line), Qt::AlignCenter, QStringLiteral("|P| = %1").arg(uiSignificant(total, 3)));
    }
    // The key: each ball's colour, the total dashed.
    double x = area.left();
    const double y = area.bottom() - line;
    for (std::size_t k = 0; k < f.bodies.size(); ++k) {
        const QString name = QString::fromStdString(f.bodies[k].id);
        p.setPen(QPen(kBodyColours[k % 2], 2.0));
        p.drawLine(QPointF(x, y + line / 2), QPointF(x + 14, y + line / 2));
        p.setPen(palette.color(QPalette::Text));
        p.drawText(QPointF(x + 17, y + metrics.ascent()), name);
        x += 17 + metrics.horizontalAdvance(name) + 10;
    }
    if (f.bodies.size() > 1) {
        p.setPen(QPen(palette.color(QPalette::Text), 1.5, Qt::DashLine));
        p.drawLine(QPointF(x, y + line / 2), QPointF(x + 14, y + line / 2));
        p.drawText(QPointF(x + 17, y + metrics.ascent()), tr("total"));
    }
}

void ConservationWidget::paintEnergy(QPainter& p, const QRectF& area, const Figure& f, const QPalette& palette)
{
    const QFontMetricsF metrics(p.font());
    const double line = metrics.height();
    p.setPen(palette.color(QPalette::Text));
    const QString title = tr("Energy (J)");
    p.drawText(QRectF(area.left(), area.top(), area.width(), line), Qt::AlignLeft, title);
    // Rows: title, the totals, the bars, "before"/"after", the key (three lines), ΔE. In a short area
    // (the stacked figures of a window 800 px high) ΔE moves up beside the title, so that the bars keep
    // some height and nothing is drawn over the key.
    const bool compact = area.height() < 7 * line + 50;
    const int rows = compact ? 6 : 7;
    const QRectF values(area.left(), area.top() + line + 2, area.width(), line);
    const QRectF body(area.left(), values.bottom() + 2, area.width(), std::max(10.0, area.height() - rows * line - 10));
    double totals[2] = {0.0, 0.0};
    for (const explain::Body& b : f.bodies) {
        totals[0] += b.translationBefore + b.rotationBefore;
        totals[1] += b.translationAfter + b.rotationAfter;
    }
    // Both bars stand on the energy the balls had after their previous events: before, the cloth's
    // share since then sits on top; after, the collision's share too. The parts add up to the total.
    const double cloth = std::max(0.0, f.lostToCloth), event = std::max(0.0, f.lostToEvent);
    const double top = std::max({totals[0] + cloth, totals[1] + cloth + event, 1e-12});
    const double barW = std::min(60.0, body.width() / 2.0 - 8.0);
    const double left = body.center().x() - barW - 4.0;
    const QColor clothColour(150, 150, 150), eventColour(170, 60, 200);
    for (int phase = 0; phase < 2; ++phase) {
        const double x = left + phase * (barW + 8.0);
        double y = body.bottom();
        for (std::size_t k = 0; k < f.bodies.size(); ++k) {
            const explain::Body& b = f.bodies[k];
            const double parts[2] = {phase == 0 ? b.translationBefore : b.translationAfter,
                                     phase == 0 ? b.rotationBefore : b.rotationAfter};
            for (int part = 0; part < 2; ++part) {
                const double h = body.height() * parts[part] / top;
                QColor c = kBodyColours[k % 2];
                if (part == 1) c = c.lighter(150);
                p.fillRect(QRectF(x, y - h, barW, h), c);
                y -= h;
            }
        }
        const double losses[2] = {phase == 1 ? event : 0.0, cloth};
        const QColor lossColours[2] = {eventColour, clothColour};
        for (int part = 0; part < 2; ++part) {
            const double h = body.height() * losses[part] / top;
            p.fillRect(QRectF(x, y - h, barW, h), QBrush(lossColours[part], Qt::BDiagPattern));
            p.setPen(QPen(lossColours[part], 1.0));
            if (h >= 1.0) p.drawRect(QRectF(x, y - h, barW, h));
            y -= h;
        }
        p.setPen(palette.color(QPalette::Text));
        p.drawText(QRectF(x - 6, body.bottom() + 1, barW + 12, line), Qt::AlignCenter, phase == 0 ? tr("before") : tr("after"));
        // The total in its own row above the bars: never over the title or a bar.
        p.drawText(QRectF(x - 10, values.top(), barW + 20, line), Qt::AlignCenter, uiSignificant(totals[phase], 3));
    }
    // The legend: each ball's colour; the light part of a bar is rotation; the hatched parts are lost.
    double x = area.left();
    const double keyY = body.bottom() + line + 3;
    for (std::size_t k = 0; k < f.bodies.size(); ++k) {
        const QString name = QString::fromStdString(f.bodies[k].id);
        p.fillRect(QRectF(x, keyY + 2, 10, line - 4), kBodyColours[k % 2]);
        p.setPen(palette.color(QPalette::Text));
        p.drawText(QPointF(x + 13, keyY + metrics.ascent()), name);
        x += 13 + metrics.horizontalAdvance(name) + 10;
    }
    p.fillRect(QRectF(x, keyY + 2, 10, line - 4), kBodyColours[0].lighter(150));
    p.drawText(QRectF(x + 13, keyY, std::max(0.0, area.right() - x - 13), line), Qt::AlignLeft,
               metrics.elidedText(tr("light: rotation"), Qt::ElideRight, std::max(0.0, area.right() - x - 13)));
    const QString lossKeys[2] = {tr("lost to the collision"), tr("lost to the cloth since the previous event")};
    const QColor lossColours[2] = {eventColour, clothColour};
    for (int part = 0; part < 2; ++part) {
        const double y = keyY + (part + 1) * line;
        p.fillRect(QRectF(area.left(), y + 2, 10, line - 4), QBrush(lossColours[part], Qt::BDiagPattern));
        p.setPen(QPen(lossColours[part], 1.0));
        p.drawRect(QRectF(area.left(), y + 2, 10, line - 4));
        p.setPen(palette.color(QPalette::Text));
        p.drawText(QRectF(area.left() + 13, y, area.width() - 13, line), Qt::AlignLeft,
                   metrics.elidedText(lossKeys[part], Qt::ElideRight, area.width() - 13));
    }
    const QString change = energyChange(totals[0], totals[1]);
    if (compact) {
        const double after = metrics.horizontalAdvance(title) + 12.0;
        const double room = std::max(0.0, area.width() - after);
        p.drawText(QRectF(area.left() + after, area.top(), room, line), Qt::AlignRight,
                   metrics.elidedText(change, Qt::ElideRight, room));
    } else {
        p.drawText(QRectF(area.left(), area.bottom() - line, area.width(), line), Qt::AlignCenter, change);
    }
}

}  // namespace cuelab
