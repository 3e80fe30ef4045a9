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
    };
    static Figure figureOf(const explain::Explanation* e);
    static void paintBoth(QPainter& p, const QRectF& area, const Figure& f, const QPalette& palette, bool stacked);
    static void paintMomenta(QPainter& p, const QRectF& area, const Figure& f, const QPalette& palette);
    static void paintEnergy(QPainter& p, const QRectF& area, const Figure& f, const QPalette& palette);

    Figure figure_;
};

}  // namespace cuelab
