#include "AimDrag.h"

#include "i18n/UiNumbers.h"

#include "CuePlacement.h"
#include "TableView.h"

#include "Aim.h"

#include <QCoreApplication>
#include <QFontMetrics>
#include <QImage>
#include <QKeyEvent>
#include <QLineF>
#include <QPainter>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace cuelab {

namespace {

constexpr double kCueGrabPx = 6.0;        // pixels beside the drawn cue's axis that grab it
constexpr double kCueSampleM = 0.01;      // m between the points of the cue tested against the cursor
constexpr double kTipMarkMinBallPx = 14.0;  // the struck ball's radius on screen below which no tip mark
constexpr double kTipMarkFacing = 0.5;    // cos of the largest angle between the ball's surface and the eye
constexpr double kTipMarkRadius = 0.13;   // of the ball's radius on screen (at least kTipMarkMinPx)
constexpr double kTipMarkMinPx = 4.0;

QString tr(const char* text) { return QCoreApplication::translate("cuelab::AimDrag", text); }

double radians(double deg) { return deg * std::numbers::pi / 180.0; }
double degrees(double rad) { return rad * 180.0 / std::numbers::pi; }
double roundTo(double value, double step) { return std::round(value / step) * step; }
QVector3D q(const Vec3& v) { return QVector3D(static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())); }
Vec3 e(const QVector3D& v) { return Vec3(v.x(), v.y(), v.z()); }
Vec2 unit(double headingDeg) { return Vec2(std::cos(radians(headingDeg)), std::sin(radians(headingDeg))); }

// A heading near `from` (the same turn, not the same angle plus 360°), kept within the Shot dock's
// ±360° and rounded to its 0.01°.
double headingNear(double from, double heading)
{
    double h = from + std::remainder(heading - from, 360.0);
    if (h > 360.0) h -= 360.0;
    if (h < -360.0) h += 360.0;
    return roundTo(h, 0.01);
}

double distanceToSegment(const QPointF& p, const QPointF& a, const QPointF& b)
{
    const QPointF ab = b - a;
    const double len2 = QPointF::dotProduct(ab, ab);
    const double t = len2 > 0.0 ? std::clamp(QPointF::dotProduct(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return QLineF(p, a + t * ab).length();
}

}  // namespace

std::optional<AimDrag::Struck> AimDrag::struck() const
{
    const ViewScene& scene = view_.scene();
    if (!scene.result || !scene.shot || view_.time() > 0.0 || !view_.overlayVisible(Overlay::CueAndAim)) return std::nullopt;
    const int index = scene.result->ballIndex(scene.shot->ball);
    const std::vector<Ball>& balls = view_.setupBalls();
    if (index < 0 || static_cast<std::size_t>(index) >= balls.size()) return std::nullopt;
    const Ball& ball = balls[static_cast<std::size_t>(index)];
    if (isOutOfPlay(ball.state.motion)) return std::nullopt;
    return Struck{index, ball};
}

std::optional<Vec3> AimDrag::tipMark() const
{
    const std::optional<Struck> s = struck();
    if (!s) return std::nullopt;
    const double r = s->ball.radius;
    const Vec3 centre(s->ball.state.position.x(), s->ball.state.position.y(), r);
    const Vec3 contact = tipContactPoint(s->ball, *view_.scene().shot);
    const Vec3 eye = e(view_.camera().eye());
    // Big enough on screen to aim at (the view's vertical field of view spans its height) ...
    const double halfFov = radians(OrbitCamera::kFieldOfViewDeg / 2.0);
    const double ballPx = r / ((eye - centre).norm() * std::tan(halfFov)) * view_.height() / 2.0;
    if (ballPx < kTipMarkMinBallPx) return std::nullopt;
    // ... and facing the eye: the player's view of the ball, not its rim.
    if ((contact - centre).normalized().dot((eye - contact).normalized()) < kTipMarkFacing) return std::nullopt;
    return contact;
}

std::optional<Vec2> AimDrag::ghostCentre() const
{
    const ViewScene& scene = view_.scene();
    if (!struck()) return std::nullopt;
    const std::optional<aim::AimGeometry> g = aim::firstContact(*scene.result);
    if (!g) return std::nullopt;
    // Only a ghost ball the view draws: the Ghost Balls overlay's, or a layer's on the same spot.
    bool drawn = view_.overlayVisible(Overlay::GhostBalls) && view_.pathScope() != BallScope::None;
    for (const auto& [name, layer] : view_.layers())
        for (const GhostTrack& ghost : layer.ghosts)
            drawn = drawn || (!ghost.positions.empty() && (ghost.positions.front() - g->ghostBall).norm() < 1e-3);
    if (!drawn) return std::nullopt;
    return g->ghostBall;
}

bool AimDrag::overCue(const QPointF& pos) const
{
    const std::optional<Struck> s = struck();
    if (!s) return false;
    const std::optional<CuePose> pose = cuePose(*view_.scene().result, view_.setupBalls(), *view_.scene().shot);
    if (!pose) return false;
    const QVector3D tip = pose->model.column(3).toVector3D();
    const QVector3D along = pose->model.column(0).toVector3D().normalized();
    const QVector3D across = pose->model.column(1).toVector3D().normalized();
    std::optional<QPointF> last;
    for (double at = 0.0; at <= pose->length; at += kCueSampleM) {
        const QVector3D p = tip + static_cast<float>(at) * along;
        const std::optional<QPointF> here = view_.widgetPointOf(p);
        if (!here) {
            last.reset();
            continue;
        }
        const std::optional<QPointF> edge = view_.widgetPointOf(p + static_cast<float>(cueStickRadius(at)) * across);
        const double grab = std::max(kCueGrabPx, edge ? QLineF(*here, *edge).length() + 2.0 : 0.0);
        if (distanceToSegment(pos, last.value_or(*here), *here) <= grab) return true;
        last = here;
    }
    return false;
}

AimHandle AimDrag::handleAt(const QPointF& pos) const
{
    const std::optional<Struck> s = struck();
    if (!s) return AimHandle::None;
    if (const std::optional<Vec3> mark = tipMark()) {
        const std::optional<QPointF> at = view_.widgetPointOf(q(*mark));
        const Ball& ball = s->ball;
        const Vec3 centre(ball.state.position.x(), ball.state.position.y(), ball.radius);
        const std::optional<QPointF> c = view_.widgetPointOf(q(centre));
        const std::optional<QPointF> rim = view_.widgetPointOf(q(centre) + static_cast<float>(ball.radius) * view_.camera().up());
        const double ballPx = c && rim ? QLineF(*c, *rim).length() : 0.0;
        if (at && QLineF(*at, pos).length() <= std::max(kTipMarkMinPx, kTipMarkRadius * ballPx) + 3.0) return AimHandle::Tip;
    }
    if (const std::optional<Vec2> g = ghostCentre()) {
        const double r = s->ball.radius;
        const QVector3D centre(static_cast<float>(g->x()), static_cast<float>(g->y()), static_cast<float>(r));
        const std::optional<QPointF> at = view_.widgetPointOf(centre);
        const std::optional<QPointF> rim = view_.widgetPointOf(centre + static_cast<float>(r) * view_.camera().up());
        const double drawn = at && rim ? QLineF(*at, *rim).length() : 0.0;
        if (at && QLineF(*at, pos).length() <= std::max(TableView::kPickRadiusPx, drawn)) return AimHandle::Ghost;
    }
    if (overCue(pos)) return AimHandle::Cue;
    return AimHandle::None;
}

std::optional<Vec2> AimDrag::clothPoint(const QPointF& pos, double radius) const
{
    const std::optional<QVector3D> p = view_.clothPointUnder(pos, static_cast<float>(radius));
    if (!p) return std::nullopt;
    return Vec2(p->x(), p->y());
}

// The point of the ball's surface under the cursor, in the frame of the tip offset: side along the
// player's right (heading turned clockwise), height up, over R. Off the ball, the point of its
// outline nearest the ray, so that the drag goes on smoothly past the rim.
std::optional<QPointF> AimDrag::faceAt(const QPointF& pos) const
{
    const Ball& ball = struck_.ball;
    const double r = ball.radius;
    const Vec3 c(ball.state.position.x(), ball.state.position.y(), r);
    const Ray ray = view_.camera().ray(view_.toNdc(pos), view_.aspect());
    const Vec3 o = e(ray.origin), d = e(ray.direction).normalized();
    // |o + t d - c|^2 = r^2: t = b - sqrt(b^2 - |c - o|^2 + r^2), b = (c - o).d (the nearer hit).
    const double b = (c - o).dot(d);
    const double disc = b * b - (c - o).squaredNorm() + r * r;
    Vec3 p = disc >= 0.0 ? Vec3(o + (b - std::sqrt(disc)) * d) : Vec3(o + b * d);
    if (disc < 0.0) p = c + r * (p - c).normalized();
    const Vec2 h = unit(from_.headingDeg);
    const Vec3 right(h.y(), -h.x(), 0.0);
    return QPointF((p - c).dot(right) / r, (p.z() - c.z()) / r);
}

bool AimDrag::begin(AimHandle handle, const QPointF& pos)
{
    const std::optional<Struck> s = struck();
    if (!s || handle == AimHandle::None) return false;
    struck_ = *s;
    from_ = sent_ = *view_.scene().shot;
    pressPos_ = lastPos_ = pos;
    gesture_.reset();
    changed_ = false;
    pressCloth_ = clothPoint(pos, struck_.ball.radius);
    pressFace_.reset();
    switch (handle) {
    case AimHandle::None: return false;
    case AimHandle::Cue:
        if (!pressCloth_) return false;
        break;
    case AimHandle::Ghost: {
        const std::optional<Vec2> g = ghostCentre();
        if (!g || !pressCloth_) return false;
        ghostGrab_ = *g - *pressCloth_;
        gesture_ = AimGesture::Ghost;
        break;
    }
    case AimHandle::Tip:
        pressFace_ = faceAt(pos);
        gesture_ = AimGesture::Tip;
        break;
    }
    handle_ = handle;
    view_.update();
    return true;
}

void AimDrag::drag(const QPointF& pos)
{
    if (handle_ == AimHandle::None) return;
    lastPos_ = pos;
    const Vec2 centre = struck_.ball.state.position;
    const double r = struck_.ball.radius;
    if (!gesture_) {
        // A cue drag's first motion: along the cue on screen pulls, across it turns.
        const Vec2 back = centre - 0.1 * unit(from_.headingDeg);
        const std::optional<QPointF> a = view_.widgetPointOf(QVector3D(static_cast<float>(centre.x()), static_cast<float>(centre.y()), static_cast<float>(r)));
        const std::optional<QPointF> b = view_.widgetPointOf(QVector3D(static_cast<float>(back.x()), static_cast<float>(back.y()), static_cast<float>(r)));
        gesture_ = AimGesture::Turn;
        if (a && b) {
            const QLineF axis(*a, *b), motion(pressPos_, pos);
            const double angle = std::min(axis.angleTo(motion), 360.0 - axis.angleTo(motion));  // 0..180
            if (std::min(angle, 180.0 - angle) <= kPullConeDeg) gesture_ = AimGesture::Pull;
        }
    }
    CueStrike shot = from_;
    switch (*gesture_) {
    case AimGesture::Turn: {
        const std::optional<Vec2> p = clothPoint(pos, r);
        if (!p || !pressCloth_) return;
        const Vec2 a = *pressCloth_ - centre, b = *p - centre;
        if (a.norm() < 1e-6 || b.norm() < 1e-6) return;
        // The cue pivots about the ball's centre: the angle from the grabbed point to the cursor.
        const double turn = degrees(std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b)));
        shot.headingDeg = headingNear(from_.headingDeg, from_.headingDeg + turn);
        break;
    }
    case AimGesture::Pull: {
        const std::optional<Vec2> p = clothPoint(pos, r);
        if (!p || !pressCloth_) return;
        const double pulled = (*p - *pressCloth_).dot(-unit(from_.headingDeg));  // m, towards the butt
        shot.speed = std::clamp(roundTo(from_.speed + kSpeedPerMetre * pulled, 0.01), 0.0, kMaxSpeed);
        break;
    }
    case AimGesture::Ghost: {
        const std::optional<Vec2> p = clothPoint(pos, r);
        if (!p) return;
        const Vec2 ghost = *p + ghostGrab_;
        if ((ghost - centre).norm() < r) return;  // no direction through the ball's own place
        shot.headingDeg = headingNear(from_.headingDeg, degrees(std::atan2(ghost.y() - centre.y(), ghost.x() - centre.x())));
        break;
    }
    case AimGesture::Tip: {
        const std::optional<QPointF> f = faceAt(pos);
        if (!f || !pressFace_) return;
        QPointF o = QPointF(from_.side, from_.height) + *f - *pressFace_;
        const double length = std::hypot(o.x(), o.y());
        if (length > kMaxTipOffset) o *= kMaxTipOffset / length;
        shot.side = roundTo(o.x(), 0.01);
        shot.height = roundTo(o.y(), 0.01);
        if (std::hypot(shot.side, shot.height) > kMaxTipOffset) {  // rounded outwards: back inside
            shot.side = std::trunc(o.x() * 100.0) / 100.0;
            shot.height = std::trunc(o.y() * 100.0) / 100.0;
        }
        break;
    }
    }
    aim(*gesture_, shot);
    view_.update();
}

void AimDrag::aim(AimGesture gesture, const CueStrike& shot)
{
    if (shot.headingDeg == sent_.headingDeg && shot.speed == sent_.speed && shot.side == sent_.side &&
        shot.height == sent_.height)
        return;
    sent_ = shot;
    changed_ = true;
    emit view_.shotAimed(gesture, shot.headingDeg, shot.speed, shot.side, shot.height);
}

void AimDrag::end()
{
    const bool changed = changed_;
    handle_ = AimHandle::None;
    gesture_.reset();
    changed_ = false;
    view_.update();
    if (changed) emit view_.shotAimFinished();
}

bool AimDrag::isAimingKey(const QKeyEvent* event)
{
    const Qt::KeyboardModifiers mods = event->modifiers() & ~Qt::KeypadModifier;
    if (!(mods & Qt::ControlModifier) || (mods & ~(Qt::ControlModifier | Qt::ShiftModifier | Qt::AltModifier))) return false;
    const int key = event->key();
    return key == Qt::Key_Left || key == Qt::Key_Right || key == Qt::Key_Up || key == Qt::Key_Down;
}

bool AimDrag::keyPress(QKeyEvent* event)
{
    if (!isAimingKey(event)) return false;
    const Qt::KeyboardModifiers mods = event->modifiers() & ~Qt::KeypadModifier;
    const int key = event->key();
    const ViewScene& scene = view_.scene();
    if (!scene.shot || handle_ != AimHandle::None) return false;
    const double scale = (mods & Qt::ShiftModifier) ? 10.0 : (mods & Qt::AltModifier) ? 0.1 : 1.0;
    if (!keyGesture_) {
        from_ = sent_ = *scene.shot;
        keyGesture_ = true;
    }
    CueStrike shot = *scene.shot;
    // Rounded to a millionth, so that repeated tenths stay the decimals they look like.
    AimGesture gesture = AimGesture::Turn;
    if (key == Qt::Key_Left || key == Qt::Key_Right) {
        const double step = (key == Qt::Key_Left ? 1.0 : -1.0) * kHeadingStepDeg * scale;
        double h = roundTo(shot.headingDeg + step, 1e-6);
        if (h > 360.0) h -= 360.0;
        if (h < -360.0) h += 360.0;
        shot.headingDeg = h;
    } else {
        gesture = AimGesture::Pull;
        const double step = (key == Qt::Key_Up ? 1.0 : -1.0) * kSpeedStep * scale;
        shot.speed = std::clamp(roundTo(shot.speed + step, 1e-6), 0.0, kMaxSpeed);
    }
    aim(gesture, shot);
    return true;
}

bool AimDrag::keyRelease(QKeyEvent* event)
{
    if (!keyGesture_ || event->isAutoRepeat()) return false;
    const int key = event->key();
    if (key != Qt::Key_Left && key != Qt::Key_Right && key != Qt::Key_Up && key != Qt::Key_Down) return false;
    keyGesture_ = false;
    const bool changed = changed_;
    changed_ = false;
    if (changed) emit view_.shotAimFinished();
    return true;
}

Qt::CursorShape AimDrag::cursorFor(AimHandle handle, bool dragging)
{
    switch (handle) {
    case AimHandle::None: return Qt::ArrowCursor;
    case AimHandle::Cue: return dragging ? Qt::ClosedHandCursor : Qt::OpenHandCursor;
    case AimHandle::Ghost: return Qt::SizeAllCursor;
    case AimHandle::Tip: return Qt::CrossCursor;
    }
    return Qt::ArrowCursor;
}

QString AimDrag::toolTipFor(AimHandle handle)
{
    switch (handle) {
    case AimHandle::None: return QString();
    case AimHandle::Cue:
        return tr("The cue: drag across it to turn it (the heading), along it to pull back for more speed or push "
                  "forward for less. Ctrl+Left/Right turns it by 0.1°, Ctrl+Up/Down changes the speed by 0.1 m/s "
                  "(with Shift ten times as much, with Alt a tenth).");
    case AimHandle::Ghost:
        return tr("The ghost ball: where the struck ball meets the first object ball. Drag it to aim: the cue line "
                  "goes through its centre.");
    case AimHandle::Tip:
        return tr("Where the cue tip meets the ball: drag it for side (left, right) and height (follow above the "
                  "centre, draw below it).");
    }
    return QString();
}

QString AimDrag::readout() const
{
    if (handle_ == AimHandle::None || !gesture_) return QString();
    const CueStrike& s = sent_;
    QString set;
    switch (*gesture_) {
    case AimGesture::Turn:
    case AimGesture::Ghost: set = tr("heading %1°").arg(uiNumber(s.headingDeg, 2)); break;
    case AimGesture::Pull: set = tr("cue speed %1 m/s").arg(uiNumber(s.speed, 2)); break;
    case AimGesture::Tip: set = tr("tip: side %1 R, height %2 R").arg(uiNumber(s.side, 2)).arg(uiNumber(s.height, 2)); break;
    }
    QStringList lines{set};
    if (const auto& result = view_.scene().result) {
        if (const std::optional<aim::AimGeometry> g = aim::firstContact(*result)) {
            const QString side = g->side == aim::CutSide::Left ? tr("left") : g->side == aim::CutSide::Right ? tr("right") : QString();
            lines << tr("cut %1° %2, ball fraction %3").arg(uiNumber(g->cutAngleDeg, 1)).arg(side).arg(uiNumber(g->ballFraction, 2)).simplified();
        } else {
            lines << tr("no object ball hit");
        }
        if (const std::optional<aim::Launch> l = aim::launchOf(*result)) lines << tr("ball speed %1 m/s").arg(uiNumber(l->speed, 2));
    }
    return lines.join(QLatin1Char('\n'));
}

void AimDrag::paint(QPainter& painter, AimHandle hovered) const
{
    const std::optional<Struck> s = struck();
    if (const std::optional<Vec3> mark = tipMark(); mark && s) {
        const Ball& ball = s->ball;
        const Vec3 centre(ball.state.position.x(), ball.state.position.y(), ball.radius);
        const std::optional<QPointF> at = view_.widgetPointOf(q(*mark));
        const std::optional<QPointF> c = view_.widgetPointOf(q(centre));
        const std::optional<QPointF> rim = view_.widgetPointOf(q(centre) + static_cast<float>(ball.radius) * view_.camera().up());
        if (at && c && rim) {
            const double radius = std::max(kTipMarkMinPx, kTipMarkRadius * QLineF(*c, *rim).length());
            const bool hot = hovered == AimHandle::Tip || handle_ == AimHandle::Tip;
            painter.save();  // the hint is this mark's alone: set on the view's painter it would stay in the GL state
            painter.setRenderHint(QPainter::Antialiasing);
            painter.setPen(QPen(QColor(20, 20, 20), 1.5));
            painter.setBrush(hot ? QColor(255, 200, 40) : QColor(70, 160, 255));
            painter.drawEllipse(*at, radius, radius);
            painter.setPen(QPen(Qt::white, 1.0));
            painter.setBrush(Qt::NoBrush);
            painter.drawEllipse(*at, radius + 1.5, radius + 1.5);
            painter.restore();
        }
    }
    const QString text = readout();
    if (text.isEmpty()) return;
    // The text is drawn into an image first, as OverlayLabels does: glyphs drawn straight onto the GL
    // widget would cache them in GL textures that outlive its context.
    const QFontMetrics metrics(painter.font());
    const QRect box = metrics.boundingRect(QRect(0, 0, 600, 200), Qt::AlignLeft, text).adjusted(-6, -4, 6, 4);
    const qreal dpr = view_.devicePixelRatioF();
    QImage image((QSizeF(box.size()) * dpr).toSize().expandedTo(QSize(1, 1)), QImage::Format_ARGB32_Premultiplied);
    image.setDevicePixelRatio(dpr);
    image.fill(Qt::transparent);
    {
        QPainter p(&image);
        p.setRenderHint(QPainter::Antialiasing);
        p.setFont(painter.font());
        p.setPen(Qt::NoPen);
        p.setBrush(QColor(15, 18, 24, 210));
        p.drawRoundedRect(QRectF(QPointF(0, 0), QSizeF(box.size())), 4, 4);
        p.setPen(QColor(240, 240, 240));
        p.drawText(QRectF(QPointF(0, 0), QSizeF(box.size())).adjusted(6, 4, -6, -4), Qt::AlignLeft | Qt::AlignTop, text);
    }
    QPointF at = lastPos_ + QPointF(18, 18);
    at.setX(std::clamp(at.x(), 2.0, std::max(2.0, view_.width() - box.width() - 2.0)));
    at.setY(std::clamp(at.y(), 2.0, std::max(2.0, view_.height() - box.height() - 2.0)));
    painter.drawImage(at, image);
}

}  // namespace cuelab
