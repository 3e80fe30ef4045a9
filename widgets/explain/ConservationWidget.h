#pragma once
// Momenta tip to tail before and after an event, with their total (PhET Collision Lab's diagram),
// and the kinetic energy before and after as stacked bars (translation, rotation): conservation, or
// its loss to the cloth and the cushion, at a glance. QPainter only.

#include "Explanation.h"

#include <QPalette>
#include <QWidget>

#include <optional>

namespace cuelab {

class ConservationWidget : public QWidget {
    Q_OBJECT
public:
    explicit ConservationWidget(QWidget* parent = nullptr);
    void setExplanation(const explain::Explanation* e);
    // Draw the momenta as seen from the pair's centre of mass (View > Centre-of-Mass Frame): p* =
    // m (v − V), equal and opposite, so each chain closes on itself (core/aim/Frames.h).
    void setCentreOfMassFrame(bool on);
    bool centreOfMassFrame() const { return centreOfMass_; }
    QSize sizeHint() const override { return {320, 240}; }

    // Narrower than kSideBySideWidth, the momenta are drawn above the energy, not beside it.
    static constexpr int kSideBySideWidth = 440;
    bool stacked() const { return width() < kSideBySideWidth; }
    // "ΔE = -0.0123 J (-2.1 %)", rounded to what matters: a change below a millionth of the energy
    // (rounding in an elastic collision) reads "ΔE = 0 J (conserved)".
    static QString energyChange(double before, double after);
    // The figure alone in print colours (black on white), for handouts: the lesson report's key
    // collision and the HTML explanation. Side by side when `area` is at least kSideBySideWidth wide.
    static void paintFigure(QPainter& p, const QRectF& area, const explain::Explanation& e);

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    struct Figure {
        std::vector<explain::Body> bodies;
        Vec2 cushionImpulse = Vec2::Zero();  // N s, the cushion's push (ball-cushion events)
        bool cushion = false;
        bool centreOfMass = false;           // the momenta in the pair's centre-of-mass frame
        Vec2 frameVelocity = Vec2::Zero();   // m/s, V of that frame (zero: the table frame)
        // The energy's parts (J, summed over the bodies): what the event took, what the cloth took
        // since each body's previous event (core/aim/Frames.h; the explanation's energyAfterPrevious).
        double lostToEvent = 0.0, lostToCloth = 0.0;
        Vec2 momentum(std::size_t body, int phase) const;  // N s, phase 0 before, 1 after
    };
    static Figure figureOf(const explain::Explanation* e, bool centreOfMass = false);
    static void paintBoth(QPainter& p, const QRectF& area, const Figure& f, const QPalette& palette, bool stacked);
    static void paintMomenta(QPainter& p, const QRectF& area, const Figure& f, const QPalette& palette);
    static void paintEnergy(QPainter& p, const QRectF& area, const Figure& f, const QPalette& palette);

    Figure figure_;
    std::optional<explain::Explanation> explanation_;  // what figure_ shows, to redraw it in another frame
    bool centreOfMass_ = false;
};

}  // namespace cuelab
