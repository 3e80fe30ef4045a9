#include "LessonReport.h"

#include "CurvePainter.h"
#include "ShotDiagram.h"
#include "ShotOutcome.h"
#include "i18n/DisplayNames.h"

#include <QFontMetricsF>
#include <QPageLayout>
#include <QPainter>
#include <QPdfWriter>
#include <QSaveFile>

#include <algorithm>
#include <cmath>

namespace cuelab {

namespace {

QFont font(double px, bool bold = false)
{
    QFont f(QStringLiteral("DejaVu Sans"));
    f.setPixelSize(std::max(1, static_cast<int>(std::lround(px))));
    f.setBold(bold);
    return f;
}

QString id(const SimulationResult& r, int ball) { return QString::fromStdString(r.balls.at(static_cast<std::size_t>(ball)).id); }
QString text(std::string_view s) { return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size())); }

// Pages are laid out on a canvas 1000 units wide (A4 portrait: 1414 high), scaled to the device.
constexpr double kWidth = 1000.0;
constexpr double kHeight = 1414.0;
constexpr double kMargin = 60.0;

class Pages {
public:
    Pages(QPdfWriter& pdf, QPainter& painter) : pdf_(pdf), p_(painter)
    {
        const QRect paint = pdf.pageLayout().paintRectPixels(pdf.resolution());
        scale_ = std::min(paint.width() / kWidth, paint.height() / kHeight);
    }
    void begin(int page, int pages, const QString& header)
    {
        if (page > 1) pdf_.newPage();
        p_.resetTransform();
        p_.scale(scale_, scale_);
        p_.setPen(QColor(110, 110, 110));
        p_.setFont(font(12));
        p_.drawText(QRectF(kMargin, 20, kWidth - 2 * kMargin, 24), Qt::AlignLeft | Qt::AlignVCenter, header);
        p_.drawText(QRectF(kMargin, kHeight - 44, kWidth - 2 * kMargin, 24), Qt::AlignRight | Qt::AlignVCenter,
                    QStringLiteral("page %1 of %2").arg(page).arg(pages));
        p_.setPen(Qt::black);
    }

private:
    QPdfWriter& pdf_;
    QPainter& p_;
    double scale_ = 1.0;
};

double paragraph(QPainter& p, double y, const QString& s, double px, bool bold = false)
{
    p.setFont(font(px, bold));
    const QRectF box = QFontMetricsF(p.font()).boundingRect(QRectF(0, 0, kWidth - 2 * kMargin, 1e6), Qt::TextWordWrap, s);
    p.drawText(QRectF(kMargin, y, kWidth - 2 * kMargin, box.height()), Qt::TextWordWrap, s);
    return y + box.height() + px * 0.6;
}

void notesAndOutcomePage(QPainter& p, const SimulationResult& r, const QString& title, const QString& notes)
{
    double y = 60.0;
    y = paragraph(p, y, title.isEmpty() ? QStringLiteral("Shot") : title, 26, true);
    y = paragraph(p, y, QStringLiteral("Lesson"), 18, true);
    y = paragraph(p, y, notes.isEmpty() ? QStringLiteral("(This setup has no notes.)") : notes, 15);
    y += 10;
    y = paragraph(p, y, QStringLiteral("Outcome"), 18, true);
    const ShotOutcome o = shotOutcome(r);
    QStringList lines;
    lines << QStringLiteral("Struck ball: %1").arg(o.struckBall >= 0 ? id(r, o.struckBall) : QStringLiteral("none (no shot)"));
    lines << QStringLiteral("First contact: %1").arg(
        o.firstContact ? QStringLiteral("%1 at %2 s").arg(id(r, o.firstContact->ball)).arg(o.firstContact->time, 0, 'f', 4)
                       : QStringLiteral("none"));
    lines << QStringLiteral("Cushions before the first contact: %1").arg(o.cushionsBeforeFirstContact);
    QStringList pocketed;
    for (const PocketedBall& b : o.pocketed)
        pocketed << QStringLiteral("%1 in %2 at %3 s").arg(id(r, b.ball), QString::fromStdString(r.table.pockets[b.pocket].id))
                        .arg(b.time, 0, 'f', 4);
    lines << QStringLiteral("Pocketed: %1").arg(pocketed.isEmpty() ? QStringLiteral("none") : pocketed.join(QStringLiteral("; ")));
    lines << QStringLiteral("Struck ball pocketed: %1").arg(o.struckBallPocketed ? QStringLiteral("yes") : QStringLiteral("no"));
    lines << QStringLiteral("The shot ends at %1 s, after %2 events.").arg(r.endTime, 0, 'f', 4).arg(r.events.size());
    y = paragraph(p, y, lines.join(QLatin1Char('\n')), 15);
    y += 10;
    y = paragraph(p, y, QStringLiteral("Balls: cushion contacts and final positions"), 18, true);
    p.setFont(font(14, true));
    const double cols[] = {kMargin, kMargin + 160, kMargin + 320, kMargin + 520};
    p.drawText(QPointF(cols[0], y + 14), QStringLiteral("ball"));
    p.drawText(QPointF(cols[1], y + 14), QStringLiteral("cushions"));
    p.drawText(QPointF(cols[2], y + 14), QStringLiteral("state"));
    p.drawText(QPointF(cols[3], y + 14), QStringLiteral("position x, y (m)"));
    y += 24;
    p.setFont(font(14));
    for (std::size_t b = 0; b < r.balls.size() && y < kHeight - 80; ++b) {
        const BallState& s = o.finalStates[b];
        p.drawText(QPointF(cols[0], y + 14), id(r, static_cast<int>(b)));
        p.drawText(QPointF(cols[1], y + 14), QString::number(o.cushionHits[b]));
        p.drawText(QPointF(cols[2], y + 14),
                   s.motion == MotionState::Pocketed ? QStringLiteral("pocketed (%1)").arg(QString::fromStdString(r.table.pockets[s.pocket].id))
                                                     : text(toString(s.motion)));
        if (s.motion != MotionState::Pocketed)
            p.drawText(QPointF(cols[3], y + 14), QStringLiteral("%1, %2").arg(s.position.x(), 0, 'f', 4).arg(s.position.y(), 0, 'f', 4));
        y += 20;
    }
}

void eventPage(QPainter& p, const SimulationResult& r, int first, int count, bool heading)
{
    double y = 60.0;
    if (heading) y = paragraph(p, y, QStringLiteral("Events"), 18, true);
    const double cols[] = {kMargin, kMargin + 50, kMargin + 160, kMargin + 300, kMargin + 480, kMargin + 680};
    p.setFont(font(13, true));
    const char* headers[] = {"#", "time (s)", "type", "balls", "cushion / pocket", "speed before \u2192 after (m/s)"};
    for (int c = 0; c < 6; ++c) p.drawText(QPointF(cols[c], y + 14), QString::fromUtf8(headers[c]));
    y += 22;
    p.setPen(QPen(QColor(160, 160, 160), 0.6));
    p.drawLine(QPointF(kMargin, y), QPointF(kWidth - kMargin, y));
    p.setPen(Qt::black);
    p.setFont(font(13));
    for (int i = first; i < std::min<int>(first + count, static_cast<int>(r.events.size())); ++i) {
        const QStringList row = LessonReport::eventRow(r, i);
        for (int c = 0; c < 6; ++c) p.drawText(QPointF(cols[c], y + 14), row[c]);
        y += 31.0;
    }
}

void plotsPage(QPainter& p, const SimulationResult& r)
{
    double y = paragraph(p, 60.0, QStringLiteral("Plots against time"), 18, true);
    const struct {
        plots::Quantity q;
        const char* title;
    } charts[] = {{plots::Quantity::Speed, "Speed"},
                  {plots::Quantity::SlipSpeed, "Slip speed at the cloth"},
                  {plots::Quantity::SpinZ, "Side spin wz"},
                  {plots::Quantity::KineticEnergy, "Kinetic energy"}};
    const double h = (kHeight - y - 80.0) / 4.0;
    for (const auto& c : charts) {
        paintChart(p, QRectF(kMargin, y, kWidth - 2 * kMargin, h - 16), QString::fromUtf8(c.title),
                   text(plots::unit(c.q)), chartLines(r, c.q), r);
        y += h;
    }
}

}  // namespace

LessonReport::LessonReport(std::shared_ptr<const SimulationResult> result, QString title, QString notes)
    : result_(std::move(result)), title_(std::move(title)), notes_(std::move(notes))
{
}

QStringList LessonReport::eventRow(const SimulationResult& r, int i)
{
    const Event& e = r.events[static_cast<std::size_t>(i)];
    const bool two = e.kind == EventKind::BallBall;
    QString balls = id(r, e.balls[0]);
    if (two) balls += QStringLiteral(", ") + id(r, e.balls[1]);
    QString where;
    if (e.kind == EventKind::BallCushion) where = QString::fromStdString(r.table.cushions[e.cushion].id);
    if (e.kind == EventKind::BallJaw) where = QString::fromStdString(r.table.jaws[e.jaw].id);
    if (e.kind == EventKind::BallPocket) where = QString::fromStdString(r.table.pockets[e.pocket].id);
    QString speeds = QStringLiteral("%1 \u2192 %2").arg(e.before[0].velocity.norm(), 0, 'f', 3).arg(e.after[0].velocity.norm(), 0, 'f', 3);
    if (two) speeds += QStringLiteral("; %1 \u2192 %2").arg(e.before[1].velocity.norm(), 0, 'f', 3).arg(e.after[1].velocity.norm(), 0, 'f', 3);
    return {eventNumber(i), QString::number(e.time, 'f', 5), text(toString(e.kind)), balls, where, speeds};
}

int LessonReport::eventPages() const
{
    const int events = result_ ? static_cast<int>(result_->events.size()) : 0;
    return std::max(1, (events + kEventRowsPerPage - 1) / kEventRowsPerPage);
}

bool LessonReport::write(const QString& path, QString* error, const Progress& progress) const
{
    if (!result_) {
        if (error) *error = QStringLiteral("%1: there is no simulation to report").arg(path);
        return false;
    }
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly)) {
        if (error) *error = QStringLiteral("%1: cannot write the file: %2").arg(path, file.errorString());
        return false;
    }
    const int pages = pageCount();
    bool cancelled = false;
    {
        QPdfWriter pdf(&file);
        pdf.setTitle(title_.isEmpty() ? QStringLiteral("CueLab lesson report") : title_);
        pdf.setCreator(QStringLiteral("CueLab"));
        pdf.setResolution(200);
        pdf.setPageLayout(QPageLayout(QPageSize(QPageSize::A4), QPageLayout::Portrait, QMarginsF(10, 10, 10, 10),
                                      QPageLayout::Millimeter));
        QPainter painter;
        if (!painter.begin(&pdf)) {
            if (error) *error = QStringLiteral("%1: cannot draw the PDF").arg(path);
            file.cancelWriting();
            return false;
        }
        painter.setRenderHint(QPainter::Antialiasing);
        Pages layout(pdf, painter);
        const QString header = QStringLiteral("CueLab lesson report \u2014 ") + (title_.isEmpty() ? QStringLiteral("untitled shot") : title_);
        int page = 1;
        auto next = [&]() {
            if (progress && !progress(page, pages)) cancelled = true;
            ++page;
            return !cancelled;
        };
        layout.begin(page, pages, header);
        const ShotDiagram diagram(result_, {title_, QString()});
        diagram.paint(painter, QRectF(kMargin, 60, kWidth - 2 * kMargin, kHeight - 140));
        if (next()) {
            layout.begin(page, pages, header);
            notesAndOutcomePage(painter, *result_, title_, notes_);
            bool going = next();
            for (int k = 0; going && k < eventPages(); ++k) {
                layout.begin(page, pages, header);
                eventPage(painter, *result_, k * kEventRowsPerPage, kEventRowsPerPage, k == 0);
                going = next();
            }
            if (going) {
                layout.begin(page, pages, header);
                plotsPage(painter, *result_);
                next();
            }
        }
        painter.end();
    }
    if (cancelled) {
        file.cancelWriting();
        if (error) *error = QStringLiteral("cancelled");
        return false;
    }
    if (!file.commit()) {
        if (error) *error = QStringLiteral("%1: cannot write the file: %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

}  // namespace cuelab
