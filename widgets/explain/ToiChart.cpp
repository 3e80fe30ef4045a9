#include "ToiChart.h"

#include "i18n/UiNumbers.h"

#include <QChart>
#include <QLegend>
#include <QLegendMarker>
#include <QLineSeries>
#include <QScatterSeries>
#include <QValueAxis>

#include <algorithm>
#include <cmath>

namespace cuelab {

ToiChart::ToiChart(QWidget* parent) : QChartView(new QChart, parent)
{
    setRenderHint(QPainter::Antialiasing);
    chart()->legend()->setAlignment(Qt::AlignBottom);
    chart()->setMargins(QMargins(2, 2, 2, 2));
    chart()->setLocalizeNumbers(true);  // axis labels in the interface's language ("0,56")
    setMinimumSize(240, 230);
    setExplanation(nullptr);
}

void ToiChart::setExplanation(const explain::Explanation* e)
{
    QChart* c = chart();
    c->removeAllSeries();
    for (QAbstractAxis* axis : c->axes()) c->removeAxis(axis), delete axis;
    tauMax_ = 0.0;
    marked_ = 0;
    if (!e || !e->toi) {
        c->setTitle(e ? tr("No time-of-impact polynomial: this event's time is closed-form")
                      : tr("Time-of-impact polynomial"));
        return;
    }
    const explain::TimeOfImpact& toi = *e->toi;
    // The window: up to twice the chosen root (so the approach and what follows show), within the
    // prediction window H; a contact at τ = 0 shows a short stretch.
    double span = toi.root > 0.0 ? 2.0 * toi.root : 0.05;
    if (std::isfinite(toi.horizon) && toi.horizon > 0.0) span = std::min(span, toi.horizon);
    tauMax_ = span;
    const bool linear = e->kind == EventKind::BallCushion || e->kind == EventKind::BallTable;  // a distance, m
    c->setTitle(tr("f(τ) from t₀ = %1 s").arg(uiSignificant(toi.t0, 6)));

    auto* curve = new QLineSeries;
    curve->setName(tr("f(τ)"));
    double lo = 0.0, hi = 0.0;
    constexpr int kSamples = 400;
    for (int k = 0; k <= kSamples; ++k) {
        const double tau = span * k / kSamples;
        const double f = toi.at(tau);
        lo = std::min(lo, f);
        hi = std::max(hi, f);
        curve->append(tau, f);
    }
    auto* zero = new QLineSeries;
    zero->setName(tr("f = 0"));
    zero->append(0.0, 0.0);
    zero->append(span, 0.0);
    zero->setPen(QPen(QColor(120, 120, 120), 1, Qt::DashLine));
    auto* roots = new QScatterSeries;
    roots->setName(tr("other roots"));
    roots->setMarkerSize(8);
    roots->setColor(QColor(90, 90, 90));
    auto* chosen = new QScatterSeries;
    chosen->setName(tr("τ* = %1 s").arg(uiSignificant(toi.root, 4)));
    chosen->setMarkerSize(13);
    chosen->setColor(QColor(220, 30, 30));
    for (const explain::ToiRoot& r : toi.roots) {
        if (r.tau < 0.0 || r.tau > span) continue;
        (r.chosen ? chosen : roots)->append(r.tau, 0.0);
        ++marked_;
    }
    c->addSeries(curve);
    c->addSeries(zero);
    c->addSeries(roots);
    c->addSeries(chosen);
    auto* x = new QValueAxis;
    x->setTitleText(tr("τ (s)"));
    x->setRange(0.0, span);
    auto* y = new QValueAxis;
    y->setTitleText(linear ? tr("f (m)") : tr("f (m²)"));
    const double pad = 0.05 * std::max(hi - lo, 1e-12);
    y->setRange(lo - pad, hi + pad);
    c->addAxis(x, Qt::AlignBottom);
    c->addAxis(y, Qt::AlignLeft);
    for (QAbstractSeries* s : c->series()) {
        s->attachAxis(x);
        s->attachAxis(y);
    }
    // The legend names what is plotted, short enough to stay whole in a narrow dock: the zero line
    // needs no entry, and roots outside the window none either.
    for (QLegendMarker* m : c->legend()->markers(zero)) m->setVisible(false);
    if (roots->count() == 0)
        for (QLegendMarker* m : c->legend()->markers(roots)) m->setVisible(false);
}

}  // namespace cuelab
