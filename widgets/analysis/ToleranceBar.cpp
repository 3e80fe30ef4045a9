#include "ToleranceBar.h"

#include "i18n/UiNumbers.h"

#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace cuelab {

namespace {

const QColor kMet(46, 160, 67);
const QColor kFailed(200, 200, 200);
const QColor kRefused(90, 90, 90);

}  // namespace

int decimalsFor(const std::string& key)
{
    if (key == "shot.heading" || key == "shot.elevation") return 2;
    return 3;
}

QString valueText(const std::string& key, double value)
{
    const QString unit = QString::fromStdString(analysis::unitOf(key)).trimmed();
    const QString number = uiNumber(value, decimalsFor(key));
    if (unit.isEmpty()) return number;
    return unit == QStringLiteral("°") ? number + unit : number + QLatin1Char(' ') + unit;
}

ToleranceBar::ToleranceBar(QString label, QWidget* parent) : QWidget(parent), label_(std::move(label))
{
    setPending(tr("not scanned"));
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
}

void ToleranceBar::setScan(const analysis::ToleranceScan& scan)
{
    scan_ = scan;
    if (scan.found) {
        text_ = tr("%1: from %2 to %3, ±%4")
                    .arg(label_, valueText(scan.key, scan.low), valueText(scan.key, scan.high), valueText(scan.key, scan.halfWidth()));
        if (scan.lowAtScanEdge || scan.highAtScanEdge) text_ += tr(" (reaches the end of the scan)");
    } else {
        text_ = tr("%1: no value in the scanned range meets the goal").arg(label_);
    }
    if (scan.found && !scan.currentMet) text_ += tr(" (the current value misses)");
    setToolTip(tr("%1 shots simulated; the window's edges are refined by bisection. Grey: misses the goal, "
                  "dark: illegal value, green: meets it; the black line is the current value.")
                   .arg(scan.shots));
    update();
}

void ToleranceBar::setPending(const QString& text)
{
    scan_.reset();
    text_ = QStringLiteral("%1: %2").arg(label_, text);
    update();
}

QSize ToleranceBar::sizeHint() const { return {360, 2 * fontMetrics().height() + 24}; }
QSize ToleranceBar::minimumSizeHint() const { return {180, 2 * fontMetrics().height() + 24}; }

void ToleranceBar::paintEvent(QPaintEvent*)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const int textHeight = fontMetrics().height();
    p.setPen(palette().color(QPalette::WindowText));
    p.drawText(QRect(2, 0, width() - 4, textHeight), Qt::AlignLeft | Qt::AlignVCenter,
               fontMetrics().elidedText(text_, Qt::ElideRight, width() - 4));
    const QRectF bar(4, textHeight + 4, width() - 8, 14);
    p.setPen(Qt::NoPen);
    p.setBrush(palette().color(QPalette::Base));
    p.drawRect(bar);
    if (!scan_ || scan_->values.empty()) return;

    const analysis::ToleranceScan& s = *scan_;
    const double from = s.values.front(), to = s.values.back();
    const double span = to > from ? to - from : 1.0;
    const auto xOf = [&](double v) { return bar.left() + (v - from) / span * bar.width(); };
    // Grid values: each owns the stretch halfway to its neighbours.
    const std::size_t n = s.values.size();
    for (std::size_t i = 0; i < n; ++i) {
        const double left = i == 0 ? from : 0.5 * (s.values[i - 1] + s.values[i]);
        const double right = i + 1 == n ? to : 0.5 * (s.values[i] + s.values[i + 1]);
        const QColor c = s.met[i] ? kMet.lighter(150) : s.status[i] == analysis::ShotStatus::Refused ? kRefused : kFailed;
        p.setBrush(c);
        p.drawRect(QRectF(xOf(left), bar.top(), std::max(1.0, xOf(right) - xOf(left)), bar.height()));
    }
    if (s.found) {
        p.setBrush(kMet);
        p.drawRect(QRectF(xOf(s.low), bar.top() + 3, std::max(1.5, xOf(s.high) - xOf(s.low)), bar.height() - 6));
    }
    p.setPen(QPen(Qt::black, 2));
    const double x = xOf(s.current);
    p.drawLine(QPointF(x, bar.top() - 2), QPointF(x, bar.bottom() + 2));
    // The scale: the scanned range's ends and the current value, under the bar.
    p.setPen(palette().color(QPalette::WindowText));
    const QRectF under(bar.left(), bar.bottom() + 2, bar.width(), textHeight);
    const QString current = valueText(s.key, s.current);
    const double w = fontMetrics().horizontalAdvance(current) + 8;
    const QRectF middle(std::clamp(x - w / 2, under.left(), under.right() - w), under.top(), w, textHeight);
    const QString left = valueText(s.key, from), right = valueText(s.key, to);
    if (fontMetrics().horizontalAdvance(left) + 4 < middle.left() - under.left())
        p.drawText(under, Qt::AlignLeft | Qt::AlignVCenter, left);
    if (fontMetrics().horizontalAdvance(right) + 4 < under.right() - middle.right())
        p.drawText(under, Qt::AlignRight | Qt::AlignVCenter, right);
    p.drawText(middle, Qt::AlignCenter, current);
}

}  // namespace cuelab
