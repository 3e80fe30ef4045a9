#include "CompareChart.h"

#include <QChart>
#include <QLegendMarker>
#include <QLineSeries>
#include <QValueAxis>

#include <algorithm>

namespace cuelab {

CompareChart::CompareChart(QWidget* parent)
    : QChartView(parent), x_(new QValueAxis), y_(new QValueAxis), cursor_(new QLineSeries)
{
    auto* c = new QChart;
    c->setLocalizeNumbers(true);  // axis labels in the interface's language ("0,56")
    c->setTitle(tr("Position error against the exact run"));
    c->legend()->setAlignment(Qt::AlignRight);
    x_->setTitleText(tr("time (s)"));
    y_->setTitleText(tr("error (mm)"));
    x_->setLabelFormat(QStringLiteral("%.2f"));
    y_->setLabelFormat(QStringLiteral("%.3g"));
    c->addAxis(x_, Qt::AlignBottom);
    c->addAxis(y_, Qt::AlignLeft);
    cursor_->setName(tr("now"));
    QPen pen(QColor(90, 90, 90));
    pen.setStyle(Qt::DashLine);
    pen.setWidthF(1.5);
    cursor_->setPen(pen);
    c->addSeries(cursor_);
    cursor_->attachAxis(x_);
    cursor_->attachAxis(y_);
    for (QLegendMarker* m : c->legend()->markers(cursor_)) m->setVisible(false);
    setChart(c);
    setRenderHint(QPainter::Antialiasing);
    setMinimumHeight(220);
    setToolTip(tr("How far each ball of the chosen engine is from the same ball in the exact simulation, "
                  "in millimetres (metres when it passes a metre), at every sample time; the dashed line is the current time"));
    clear();
}

void CompareChart::clear()
{
    for (QLineSeries* s : balls_) {
        chart()->removeSeries(s);
        delete s;
    }
    balls_.clear();
    x_->setRange(0.0, 1.0);
    y_->setRange(0.0, 1.0);
    placeCursor();
}

void CompareChart::setComparison(const compare::Comparison& comparison)
{
    clear();
    const compare::Divergence& d = comparison.divergence;
    // Millimetres, or metres once an error passes a metre (a run that sends a ball elsewhere):
    // "1.5 m", never "1.5e+03 mm".
    double largest = 0.0;
    for (const auto& errors : d.error)
        for (double e : errors) largest = std::max(largest, e);
    const bool inMetres = largest >= 1.0;
    const double scale = inMetres ? 1.0 : 1000.0;
    y_->setTitleText(inMetres ? tr("error (m)") : tr("error (mm)"));
    y_->setLabelFormat(inMetres ? QStringLiteral("%.2f") : QStringLiteral("%.3g"));
    double top = 0.0;
    for (std::size_t i = 0; i < d.error.size(); ++i) {
        auto* s = new QLineSeries;
        s->setName(QString::fromStdString(comparison.run.ids[i]));
        QList<QPointF> points;
        points.reserve(static_cast<qsizetype>(d.times.size()));
        for (std::size_t k = 0; k < d.times.size(); ++k) {
            points.append(QPointF(d.times[k], scale * d.error[i][k]));
            top = std::max(top, scale * d.error[i][k]);
        }
        s->replace(points);
        chart()->addSeries(s);
        s->attachAxis(x_);
        s->attachAxis(y_);
        balls_.append(s);
    }
    x_->setRange(0.0, std::max(d.times.empty() ? 1.0 : d.times.back(), 1e-3));
    y_->setRange(0.0, top > 0.0 ? 1.05 * top : 1.0);
    y_->applyNiceNumbers();
    placeCursor();
}

QString CompareChart::errorAxisTitle() const { return y_->titleText(); }

void CompareChart::setTime(double t)
{
    cursorTime_ = t;
    placeCursor();
}

void CompareChart::placeCursor()
{
    cursor_->replace(QList<QPointF>{QPointF(cursorTime_, y_->min()), QPointF(cursorTime_, y_->max())});
}

}  // namespace cuelab
