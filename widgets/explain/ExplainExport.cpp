#include "ExplainExport.h"

#include "i18n/UiNumbers.h"

#include "Explain.h"
#include "ExplainLanguage.h"
#include "ExplainText.h"

#include "ConservationWidget.h"

#include <QBuffer>
#include <QFileInfo>
#include <QFontMetricsF>
#include <QPainter>
#include <QPainterPath>
#include <QSaveFile>
#include <QSvgGenerator>

#include <algorithm>
#include <cmath>
#include <functional>

namespace cuelab {

namespace {

constexpr int kFigureWidth = 640;   // px, the figures of the HTML handout
constexpr int kFigureHeight = 260;

// The time-of-impact polynomial over its window, with f = 0 and the chosen root: the Explain dock's
// chart drawn for print.
void paintToi(QPainter& p, const QRectF& area, const explain::TimeOfImpact& toi)
{
    p.fillRect(area, Qt::white);
    double span = toi.root > 0.0 ? 2.0 * toi.root : 0.05;
    if (std::isfinite(toi.horizon) && toi.horizon > 0.0) span = std::min(span, toi.horizon);
    constexpr int kSamples = 300;
    double lo = 0.0, hi = 0.0;
    for (int k = 0; k <= kSamples; ++k) {
        const double f = toi.at(span * k / kSamples);
        lo = std::min(lo, f);
        hi = std::max(hi, f);
    }
    if (hi - lo <= 0.0) hi = lo + 1.0;
    const QFontMetricsF metrics(p.font());
    const double line = metrics.height();
    const QRectF plot = area.adjusted(70, line + 6, -10, -2 * line - 6);
    const auto at = [&](double tau, double f) {
        return QPointF(plot.left() + plot.width() * tau / span, plot.bottom() - plot.height() * (f - lo) / (hi - lo));
    };
    p.setPen(Qt::black);
    p.drawText(QRectF(area.left(), area.top(), area.width(), line), Qt::AlignHCenter,
               QObject::tr("f(τ), the gap, from t₀ = %1 s").arg(uiSignificant(toi.t0, 6)));
    p.setPen(QPen(QColor(150, 150, 150), 1.0));
    p.drawRect(plot);
    p.setPen(QPen(QColor(120, 120, 120), 1.0, Qt::DashLine));
    p.drawLine(at(0.0, 0.0), at(span, 0.0));
    QPainterPath curve;
    for (int k = 0; k <= kSamples; ++k) {
        const double tau = span * k / kSamples;
        if (k == 0) curve.moveTo(at(tau, toi.at(tau)));
        else curve.lineTo(at(tau, toi.at(tau)));
    }
    p.setPen(QPen(QColor(40, 110, 220), 2.0));
    p.setBrush(Qt::NoBrush);
    p.drawPath(curve);
    p.setPen(QPen(QColor(200, 40, 40), 2.0));
    p.setBrush(QColor(200, 40, 40));
    const QPointF root = at(toi.root, 0.0);
    p.drawEllipse(root, 4, 4);
    p.setPen(Qt::black);
    p.drawText(QRectF(area.left(), plot.top(), 66, line), Qt::AlignRight, uiSignificant(hi, 3));
    p.drawText(QRectF(area.left(), plot.bottom() - line, 66, line), Qt::AlignRight, uiSignificant(lo, 3));
    p.drawText(QRectF(plot.left(), plot.bottom() + 2, plot.width(), line), Qt::AlignLeft, QStringLiteral("0"));
    p.drawText(QRectF(plot.left(), plot.bottom() + 2, plot.width(), line), Qt::AlignRight, QObject::tr("τ = %1 s").arg(uiSignificant(span, 4)));
    p.drawText(QRectF(plot.left(), plot.bottom() + line + 2, plot.width(), line), Qt::AlignHCenter,
               QObject::tr("blue: f(τ); dashed: f = 0; red dot: the chosen root τ* = %1 s").arg(uiSignificant(toi.root, 6)));
}

// A figure as an inline <svg> element (no XML prolog), to embed in the HTML.
QString inlineSvg(const std::function<void(QPainter&, const QRectF&)>& paint, const QString& title)
{
    QBuffer buffer;
    buffer.open(QIODevice::WriteOnly);
    QSvgGenerator svg;
    svg.setOutputDevice(&buffer);
    svg.setSize(QSize(kFigureWidth, kFigureHeight));
    svg.setViewBox(QRect(0, 0, kFigureWidth, kFigureHeight));
    svg.setTitle(title);
    {
        QPainter p(&svg);
        p.setRenderHint(QPainter::Antialiasing);
        QFont font(QStringLiteral("DejaVu Sans"));
        font.setPixelSize(12);
        p.setFont(font);
        paint(p, QRectF(0, 0, kFigureWidth, kFigureHeight));
    }
    QString text = QString::fromUtf8(buffer.data());
    const qsizetype start = text.indexOf(QLatin1String("<svg"));
    return start >= 0 ? text.mid(start) : text;
}

// One explanation with its figures: the time-of-impact polynomial and the momenta and energies.
std::string htmlWithFigures(const explain::Explanation& e)
{
    QString figures;
    if (e.toi)
        figures += QStringLiteral("<figure class=\"toi\">") +
                   inlineSvg([&](QPainter& p, const QRectF& r) { paintToi(p, r, *e.toi); }, QObject::tr("Time of impact")) +
                   QStringLiteral("</figure>\n");
    if (!e.bodies.empty())
        figures += QStringLiteral("<figure class=\"conservation\">") +
                   inlineSvg([&](QPainter& p, const QRectF& r) { ConservationWidget::paintFigure(p, r, e); },
                             QObject::tr("Momentum and energy")) +
                   QStringLiteral("</figure>\n");
    return explain::toHtml(e, explainLanguage()) + "\n" + figures.toStdString();
}

std::string htmlDocument(const std::vector<explain::Explanation>& all, const std::string& title)
{
    const QString heading = QString::fromStdString(title).toHtmlEscaped();
    std::string out = "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>" + heading.toStdString() +
                      "</title></head><body style=\"font-family:sans-serif\">\n<h1>" + heading.toStdString() + "</h1>\n";
    for (const explain::Explanation& e : all) out += htmlWithFigures(e) + "\n<hr>\n";
    out += "</body></html>\n";
    return out;
}

}  // namespace

std::vector<int> collisionEvents(const SimulationResult& result)
{
    std::vector<int> out;
    for (std::size_t i = 0; i < result.events.size(); ++i)
        if (isCollision(result.events[i].kind) || result.events[i].kind == EventKind::BallPocket) out.push_back(int(i));
    return out;
}

bool exportExplanations(const QString& path, const SimulationResult& result, const std::optional<CueStrike>& shot,
                        const std::vector<int>& events, const QString& title, QString* error)
{
    std::vector<explain::Explanation> all;
    for (int i : events) {
        if (i < 0 || i >= int(result.events.size())) {
            if (error) *error = QObject::tr("no event %1 in this shot").arg(QString::fromStdString(explain::eventNumber(i)));
            return false;
        }
        // Synchronous, within the core's budget for running the shot again (a held group's solve) per
        // event: the events of one result share a run again, and one out of time is not repeated for
        // the later events; past the budget the solves are left out, and the text says so.
        all.push_back(explain::explain(result, i, shot, explain::ExplainLimits{}));
    }
    const QString suffix = QFileInfo(path).suffix().toLower();
    const bool markdown = suffix == QLatin1String("md") || suffix == QLatin1String("markdown");
    const std::string text = markdown ? explain::toMarkdown(all, title.toStdString(), explainLanguage())
                                      : htmlDocument(all, title.toStdString());
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly)) {
        if (error) *error = QObject::tr("%1: %2").arg(QFileInfo(path).fileName(), file.errorString());
        return false;
    }
    file.write(text.data(), qint64(text.size()));
    if (!file.commit()) {
        if (error) *error = QObject::tr("%1: %2").arg(QFileInfo(path).fileName(), file.errorString());
        return false;
    }
    return true;
}

}  // namespace cuelab
