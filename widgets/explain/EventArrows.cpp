#include "EventArrows.h"

#include "i18n/UiNumbers.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>

namespace cuelab {

namespace {

constexpr double kShortestArrow = 1e-4;        // m: shorter arrows (a ball at rest) are not drawn
constexpr double kVerticalImpulseShown = 5e-4;  // N·s: a smaller vertical impulse rounds to 0.000 in the label

// The context lupdate gives tr() calls in functions of namespace cuelab (resources/translations).
QString tr(const char* text) { return QCoreApplication::translate("cuelab", text); }

QString newtonSeconds(double value) { return uiNumber(value, 3); }

}  // namespace

double arrowPlaneHeight(const explain::Explanation& e)
{
    double top = 0.0;
    for (const explain::Body& b : e.bodies) top = std::max(top, 2.0 * b.radius);
    return top + kArrowPlaneLift;
}

Vec2 framedMomentum(const explain::Explanation& e, std::size_t body, int phase, ArrowFrame frame)
{
    const explain::Body& b = e.bodies.at(body);
    const Vec2 p = phase == 0 ? b.momentumBefore() : b.momentumAfter();
    if (frame == ArrowFrame::Table || e.bodies.size() != 2) return p;
    std::vector<aim::FrameBody> bodies;
    for (const explain::Body& x : e.bodies) bodies.push_back({x.mass, x.before.velocity, x.after.velocity});
    return p - b.mass * aim::centreOfMassFrame(bodies).velocity;
}

ViewLayer eventArrowsLayer(const explain::Explanation& e, const EventArrowColours& colours)
{
    return eventArrowsLayer(e, ArrowFrame::Table, colours);
}

ViewLayer eventArrowsLayer(const explain::Explanation& e, ArrowFrame frame, const EventArrowColours& colours)
{
    const bool starred = frame == ArrowFrame::CentreOfMass && e.bodies.size() == 2;
    ViewLayer layer;
    if (!isCollision(e.kind) || !e.hasContact || e.bodies.empty()) return layer;
    const double z = arrowPlaneHeight(e);
    const Vec3 contact(e.contactPoint.x(), e.contactPoint.y(), z);

    LayerMarker& marker = layer.markers.emplace_back();
    marker.position = contact;
    marker.colour = colours.contact;
    marker.size = 12.0f;
    marker.label = tr("contact");
    layer.legend = starred ? tr("Arrows: 1 N·s = %1 m; momenta p* in the centre-of-mass frame").arg(kArrowMetresPerNewtonSecond)
                           : tr("Arrows: 1 N·s = %1 m").arg(kArrowMetresPerNewtonSecond);

    for (std::size_t k = 0; k < e.bodies.size(); ++k) {
        const explain::Body& b = e.bodies[k];
        const QString id = QString::fromStdString(b.id);
        // Each ball's own pair of colours: the second ball's arrows never look like the first's.
        const QColor pBefore = k == 0 ? colours.momentumBefore : colours.secondMomentumBefore;
        const QColor pAfter = k == 0 ? colours.momentumAfter : colours.secondMomentumAfter;
        const Vec3 centre(b.before.position.x(), b.before.position.y(), z);
        const Vec2 before = framedMomentum(e, k, 0, frame), after = framedMomentum(e, k, 1, frame);
        if (kArrowMetresPerNewtonSecond * before.norm() >= kShortestArrow)
            layer.arrows.push_back({centre, centre + kArrowMetresPerNewtonSecond * Vec3(before.x(), before.y(), 0.0),
                                    pBefore, 3.5f,
                                    starred ? tr("p* %1 = %2 N·s").arg(id, newtonSeconds(before.norm()))
                                            : tr("p %1 = %2 N·s").arg(id, newtonSeconds(before.norm()))});
        if (kArrowMetresPerNewtonSecond * after.norm() >= kShortestArrow)
            layer.arrows.push_back({centre, centre + kArrowMetresPerNewtonSecond * Vec3(after.x(), after.y(), 0.0),
                                    pAfter, 3.5f,
                                    starred ? tr("p*′ %1 = %2 N·s").arg(id, newtonSeconds(after.norm()))
                                            : tr("p′ %1 = %2 N·s").arg(id, newtonSeconds(after.norm()))});
    }
    // The impulse by its horizontal part (see the header), its vertical part, if any, in the label;
    // then the normal, drawn last, on top: it lies along the line of centres, under the second
    // ball's momentum after a frictionless hit.
    const Vec3 horizontal(e.impulse.x(), e.impulse.y(), 0.0);
    const QString magnitude = newtonSeconds(horizontal.norm());
    layer.arrows.push_back({contact, contact + kArrowMetresPerNewtonSecond * horizontal, colours.impulse, 4.0f,
                            std::abs(e.impulse.z()) < kVerticalImpulseShown
                                ? tr("J = %1 N·s").arg(magnitude)
                                : tr("J = %1 N·s, vertical %2 N·s").arg(magnitude, newtonSeconds(e.impulse.z()))});
    const Vec3 normal(e.normal.x(), e.normal.y(), 0.0);
    layer.arrows.push_back({contact, contact + kNormalArrowLength * normal, colours.normal, 2.0f, tr("n")});
    return layer;
}

}  // namespace cuelab
