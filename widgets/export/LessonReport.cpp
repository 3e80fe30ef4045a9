#include "LessonReport.h"

#include "i18n/UiNumbers.h"
#include "editor/RunState.h"

#include "CurvePainter.h"
#include "ShotDiagram.h"
#include "ShotOutcome.h"
#include "Verdict.h"
#include "Explain.h"
#include "ExplainText.h"
#include "explain/ConservationWidget.h"
#include "explain/ExplainLanguage.h"
#include "i18n/DisplayNames.h"
#include "lesson/PredictionText.h"

#include <QCoreApplication>

#include <QFontMetricsF>
#include <QPageLayout>
#include <QPainter>
#include <QPdfWriter>
#include <QSaveFile>
#include <QTextDocument>

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

// The context lupdate gives tr() calls in functions of namespace cuelab (resources/translations).
QString tr(const char* text) { return QCoreApplication::translate("cuelab", text); }

QString id(const SimulationResult& r, int ball) { return QString::fromStdString(r.balls.at(static_cast<std::size_t>(ball)).id); }
QString text(std::string_view s) { return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size())); }

// Pages are laid out on a canvas 1000 units wide (A4 portrait: 1414 high), scaled to the device.
constexpr double kWidth = LessonReport::kPageWidth;
constexpr double kHeight = LessonReport::kPageHeight;
constexpr double kMargin = 60.0;
constexpr double kColumnGap = 14.0;  // between the columns of a table
constexpr double kSmallestPx = 9.0;  // a table too wide for the page is set smaller, down to this

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
                    QCoreApplication::translate("cuelab", "page %1 of %2").arg(page).arg(pages));
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

// A two-column table of facts (name, value) from `y`, `width` wide at `x`; returns the y below it.
double factTable(QPainter& p, double x, double y, double width, const QString& heading, const QList<Fact>& facts)
{
    p.setFont(font(15, true));
    p.drawText(QPointF(x, y + 15), heading);
    y += 24;
    const double nameWidth = width * 0.5;
    for (const Fact& f : facts) {
        p.setFont(font(13));
        p.setPen(QColor(70, 70, 70));
        const QRectF name(x, y, nameWidth - 6, 1e4);
        const QRectF nameBox = QFontMetricsF(p.font()).boundingRect(name, Qt::TextWordWrap, f.name);
        p.drawText(name, Qt::TextWordWrap, f.name);
        p.setPen(Qt::black);
        const QRectF value(x + nameWidth, y, width - nameWidth, 1e4);
        const QRectF valueBox = QFontMetricsF(p.font()).boundingRect(value, Qt::TextWordWrap, f.value);
        p.drawText(value, Qt::TextWordWrap, f.value);
        y += std::max(nameBox.height(), valueBox.height()) + 4;
    }
    return y;
}

// The columns of a table: each as wide as its widest cell, or the longest word of its heading (the
// heading wraps word by word), kColumnGap apart. Languages whose words are longer than English's
// must not run one column into the next: a table wider than the page is set in a smaller font.
struct Columns {
    std::vector<double> x;
    std::vector<double> width;
    double px = 13.0;       // the cells' font size
    double headerHeight = 0.0;
};

Columns fitColumns(const QStringList& headers, const std::vector<QStringList>& rows, double px, double available)
{
    const auto natural = [&](double size) {
        std::vector<double> widths(static_cast<std::size_t>(headers.size()), 0.0);
        const QFontMetricsF cell(font(size));
        const QFontMetricsF heading(font(size, true));
        for (qsizetype c = 0; c < headers.size(); ++c) {
            double& w = widths[static_cast<std::size_t>(c)];
            for (const QString& word : headers[c].split(QLatin1Char(' '), Qt::SkipEmptyParts)) w = std::max(w, heading.horizontalAdvance(word));
            for (const QStringList& row : rows)
                if (c < row.size()) w = std::max(w, cell.horizontalAdvance(row[c]));
        }
        return widths;
    };
    Columns cols;
    cols.px = px;
    std::vector<double> widths = natural(px);
    const auto total = [&] {
        double sum = kColumnGap * static_cast<double>(std::max<qsizetype>(0, headers.size() - 1));
        for (const double w : widths) sum += w;
        return sum;
    };
    if (total() > available) {
        cols.px = std::max(kSmallestPx, px * available / total());
        widths = natural(cols.px);
    }
    // The room left over goes to the columns evenly, so that the table spans the page.
    const double spare = std::max(0.0, available - total()) / static_cast<double>(std::max<qsizetype>(1, headers.size()));
    double x = kMargin;
    const QFontMetricsF heading(font(cols.px, true));
    for (std::size_t c = 0; c < widths.size(); ++c) {
        cols.x.push_back(x);
        cols.width.push_back(widths[c] + spare);
        cols.headerHeight = std::max(cols.headerHeight, heading.boundingRect(QRectF(0, 0, widths[c] + spare, 1e4), Qt::TextWordWrap,
                                                                             headers[static_cast<qsizetype>(c)]).height());
        x += widths[c] + spare + kColumnGap;
    }
    return cols;
}

// The headings of a table (bold, wrapped within their columns) and a rule under them; returns the y
// below the rule.
double tableHeader(QPainter& p, double y, const Columns& cols, const QStringList& headers)
{
    p.setFont(font(cols.px, true));
    for (std::size_t c = 0; c < cols.x.size(); ++c)
        p.drawText(QRectF(cols.x[c], y, cols.width[c], cols.headerHeight), Qt::TextWordWrap | Qt::AlignLeft | Qt::AlignBottom,
                   headers[static_cast<qsizetype>(c)]);
    y += cols.headerHeight + 5;
    p.setPen(QPen(QColor(160, 160, 160), 0.6));
    p.drawLine(QPointF(kMargin, y), QPointF(kWidth - kMargin, y));
    p.setPen(Qt::black);
    return y + 3;
}

// One row of a table in the cells' font, each cell within its column; returns the y below it.
double tableRow(QPainter& p, double y, const Columns& cols, const QStringList& cells, double height)
{
    p.setFont(font(cols.px));
    for (std::size_t c = 0; c < cols.x.size() && static_cast<qsizetype>(c) < cells.size(); ++c)
        p.drawText(QRectF(cols.x[c], y, cols.width[c], height), Qt::AlignLeft | Qt::AlignVCenter, cells[static_cast<qsizetype>(c)]);
    return y + height;
}

void notesAndOutcomePage(QPainter& p, const SimulationResult& r, const QString& title, const QString& notes,
                         const ShotFacts& facts, const QStringList& noteChanges, const std::optional<GameSpec>& game)
{
    double y = 60.0;
    y = paragraph(p, y, title.isEmpty() ? tr("Shot") : title, 26, true);
    y = paragraph(p, y, tr("Lesson"), 18, true);
    y = paragraph(p, y, notes.isEmpty() ? tr("(This setup has no notes.)") : notes, 15);
    if (!noteChanges.isEmpty()) {
        p.setPen(QColor(170, 60, 0));
        y = paragraph(p, y, tr("Note: these notes were written for the shot before these changes: %1. The tables and "
                               "figures of this report are the shot as it is now.")
                                .arg(noteChanges.join(QStringLiteral("; "))),
                      14, true);
        p.setPen(Qt::black);
    }
    if (!facts.shot.isEmpty() || !facts.physics.isEmpty()) {
        y += 6;
        const double half = (kWidth - 2 * kMargin - 30) / 2;
        const double left = facts.shot.isEmpty() ? y : factTable(p, kMargin, y, half, tr("The shot"), facts.shot);
        const double right = factTable(p, kMargin + half + 30, y, half, tr("The physics"), facts.physics);
        y = std::max(left, right) + 10;
    }
    y += 6;
    y = paragraph(p, y, tr("Outcome"), 18, true);
    const ShotOutcome o = shotOutcome(r);
    QStringList lines;
    lines << tr("Struck ball: %1").arg(o.struckBall >= 0 ? id(r, o.struckBall) : tr("none (no shot)"));
    lines << tr("First contact: %1").arg(
        o.firstContact ? tr("%1 at %2 s").arg(id(r, o.firstContact->ball)).arg(uiNumber(o.firstContact->time, 4)) : tr("none"));
    lines << tr("Cushions before the first contact: %1").arg(o.cushionsBeforeFirstContact);
    QStringList pocketed;
    for (const PocketedBall& b : o.pocketed)
        pocketed << tr("%1 in the %2 at %3 s").arg(id(r, b.ball), displayElementName(r.table.pockets[b.pocket].id)).arg(uiNumber(b.time, 4));
    lines << tr("Pocketed: %1").arg(pocketed.isEmpty() ? tr("none") : pocketed.join(QStringLiteral("; ")));
    lines << tr("Struck ball pocketed: %1").arg(o.struckBallPocketed ? tr("yes") : tr("no"));
    // The verdict of the setup's game (issue 43), with the event that decides it.
    if (const std::optional<rules::Verdict> verdict = game && r.finished() ? rules::judgeShot(r, *game) : std::nullopt)
        lines << tr("Verdict: %1").arg(translated(verdict->text) +
                                         (verdict->event >= 0 ? QStringLiteral(" (#%1)").arg(verdict->event + 1) : QString()));
    // A partial run (still going, cancelled, cut short) is said to be one (issue 39).
    const QString unfinished = RunState::unfinishedNote(r);
    lines << (unfinished.isEmpty() ? tr("The shot ends at %1 s, after %2 events.").arg(uiNumber(r.endTime, 4)).arg(r.events.size())
                                   : unfinished + QLatin1Char('.'));
    y = paragraph(p, y, lines.join(QLatin1Char('\n')), 15);
    y += 10;
    y = paragraph(p, y, tr("Balls: cushion contacts and final positions"), 18, true);
    p.setFont(font(14, true));
    const double cols[] = {kMargin, kMargin + 160, kMargin + 320, kMargin + 600};
    p.drawText(QPointF(cols[0], y + 14), tr("ball"));
    p.drawText(QPointF(cols[1], y + 14), tr("cushions"));
    p.drawText(QPointF(cols[2], y + 14), tr("state"));
    p.drawText(QPointF(cols[3], y + 14), tr("position x, y (m)"));
    y += 24;
    p.setFont(font(14));
    for (std::size_t b = 0; b < r.balls.size() && y < kHeight - 80; ++b) {
        const BallState& s = o.finalStates[b];
        p.drawText(QPointF(cols[0], y + 14), id(r, static_cast<int>(b)));
        p.drawText(QPointF(cols[1], y + 14), QString::number(o.cushionHits[b]));
        p.drawText(QPointF(cols[2], y + 14),
                   s.motion == MotionState::Pocketed ? tr("in the %1").arg(displayElementName(r.table.pockets[s.pocket].id))
                                                     : displayName(s.motion));
        if (s.motion != MotionState::Pocketed)
            p.drawText(QPointF(cols[3], y + 14), QStringLiteral("%1%2%3").arg(uiNumber(s.position.x(), 4), uiListSeparator(), uiNumber(s.position.y(), 4)));
        y += 20;
    }
}

// The key collision's derivation: its title, the momentum and energy figure, then every step (title,
// law, formula, results) as far as the page goes.
void keyCollisionPage(QPainter& p, const SimulationResult& r, const std::optional<CueStrike>& shot)
{
    double y = paragraph(p, 60.0, tr("The key collision, derived"), 18, true);
    const int index = LessonReport::keyCollision(r);
    if (index < 0) {
        paragraph(p, y, tr("This shot has no collision."), 15);
        return;
    }
    // (Within the core's budget for running the shot again: a held group's solve past it is left
    // out of the page, which says so.)
    const explain::Explanation e = explain::explain(r, index, shot, explain::ExplainLimits{});
    y = paragraph(p, y, QStringLiteral("%1 %2 (%3 s)").arg(eventNumber(index), translated(e.title)).arg(uiNumber(e.time, 4)), 15, true);
    if (!e.model.empty()) y = paragraph(p, y, tr("Model: %1").arg(translated(e.model)), 13);
    p.setFont(font(13));
    const QRectF figure(kMargin, y, kWidth - 2 * kMargin, 300);
    ConservationWidget::paintFigure(p, figure, e);
    p.setPen(QPen(QColor(160, 160, 160), 0.6));
    p.setBrush(Qt::NoBrush);
    p.drawRect(figure);
    p.setPen(Qt::black);
    y = figure.bottom() + 14;
    const double bottom = kHeight - 70;
    for (const explain::Step& step : e.steps) {
        // Rich text: subscripts as subscripts (u₀,ₓ rather than u_(0,x)).
        // Design metrics: laid out as printed, not as hinted for the screen's pixels.
        QTextDocument body;
        body.setUseDesignMetrics(true);
        body.setDocumentMargin(0);
        body.setDefaultFont(font(12));
        body.setTextWidth(kWidth - 2 * kMargin);
        body.setHtml(LessonReport::stepHtml(step));
        QTextDocument title;
        title.setUseDesignMetrics(true);
        title.setDocumentMargin(0);
        title.setDefaultFont(font(13, true));
        title.setTextWidth(kWidth - 2 * kMargin);
        title.setHtml(QStringLiteral("<b>%1</b>").arg(QString::fromStdString(explain::markupToHtml(translated(step.title).toStdString()))));
        const double need = title.size().height() + body.size().height() + 24;
        if (y + need > bottom) {
            paragraph(p, y, tr("… the rest of the derivation: File → Export → Explanation."), 12);
            return;
        }
        for (QTextDocument* d : {&title, &body}) {
            p.save();
            p.translate(kMargin, y);
            d->drawContents(&p);
            p.restore();
            y += d->size().height() + (d == &title ? 2.0 : 8.0);
        }
    }
}

}  // namespace

QString LessonReport::stepHtml(const explain::Step& step)
{
    const auto html = [](const explain::Text& t) { return QString::fromStdString(explain::markupToHtml(translated(t).toStdString())); };
    QString out;
    const QString law = html(step.law);
    if (!law.isEmpty()) out += QStringLiteral("<p style=\"margin:0\">%1</p>").arg(law);
    if (!step.formula.empty()) out += QStringLiteral("<p style=\"margin:2px 0 0 0\"><i>%1</i></p>").arg(html(step.formula));
    QStringList results;
    for (const explain::Quantity& q : step.results)
        results << QStringLiteral("%1 = %2%3").arg(QString::fromStdString(explain::markupToHtml(translated(q.symbol).toStdString())),
                                                  QString::fromStdString(explain::readable(q.value, q.scale)).toHtmlEscaped(),
                                                  q.unit.empty() ? QString() : QLatin1Char(' ') + QString::fromStdString(q.unit).toHtmlEscaped());
    if (!results.isEmpty()) out += QStringLiteral("<p style=\"margin:2px 0 0 0\">%1</p>").arg(results.join(QStringLiteral(", &nbsp;")));
    return out;
}

namespace {

void eventPage(QPainter& p, const SimulationResult& r, int first, int count, bool heading)
{
    double y = 60.0;
    if (heading) y = paragraph(p, y, tr("Events"), 18, true);
    const QStringList headers = {QStringLiteral("#"), tr("time (s)"), tr("type"), tr("balls"), tr("cushion / pocket"),
                                 tr("speed before \u2192 after (m/s)")};
    std::vector<QStringList> rows;
    for (int i = first; i < std::min<int>(first + count, static_cast<int>(r.events.size())); ++i) rows.push_back(LessonReport::eventRow(r, i));
    const Columns cols = fitColumns(headers, rows, 13.0, kWidth - 2 * kMargin);
    y = tableHeader(p, y, cols, headers);
    for (const QStringList& row : rows) y = tableRow(p, y, cols, row, 31.0);
}

// The lesson's questions: each with where the shot stops, then per asked ball the guess, where it
// went, the angle between them and the score; the question's score and, over the answered ones, the
// mean.
void questionsPage(QPainter& p, const SimulationResult& r, const std::vector<ReportQuestion>& questions)
{
    double y = paragraph(p, 60.0, tr("Predictions"), 18, true);
    double sum = 0.0;
    int answered = 0;
    for (const ReportQuestion& q : questions)
        if (!q.answers.empty()) {
            sum += lesson::questionScore(q.answers);
            ++answered;
        }
    y = paragraph(p, y,
                  answered > 0 ? tr("Mean score %1 over %2 of %3 questions answered.").arg(PredictionText::score(sum / answered)).arg(answered).arg(questions.size())
                               : tr("No question answered yet: %1 to ask.").arg(questions.size()),
                  15);
    const QStringList headers = {tr("ball"), tr("guess"), tr("went"), tr("error"), tr("score")};
    for (std::size_t n = 0; n < questions.size() && y < kHeight - 160; ++n) {
        const ReportQuestion& q = questions[n];
        const QString prompt = PredictionText::prompt(q.asked);
        y += 8;
        y = paragraph(p, y, tr("Question %1: %2").arg(n + 1).arg(prompt), 15, true) - 4;
        QString stops = tr("The shot stops before %1 at %2 s").arg(eventNumber(q.asked.event)).arg(uiNumber(q.asked.time, 3));
        if (!q.answers.empty()) stops += QStringLiteral(" \u2014 ") + tr("score %1").arg(PredictionText::score(lesson::questionScore(q.answers)));
        y = paragraph(p, y, stops, 13);
        std::vector<QStringList> rows;
        for (std::size_t b = 0; b < q.asked.balls.size(); ++b) {
            const int ball = q.asked.balls[b];
            const QString name = ball >= 0 && ball < static_cast<int>(r.balls.size()) ? id(r, ball) : QString::number(ball);
            if (b >= q.answers.size()) {
                rows.push_back({name, tr("not answered"), QString(), QString(), QString()});
                continue;
            }
            const lesson::BallReveal& a = q.answers[b];
            rows.push_back({name, a.predicted.answered ? PredictionText::heading(a.predicted.headingDeg) : PredictionText::verdict(lesson::Verdict::NoAnswer),
                            PredictionText::heading(a.actualDeg),
                            PredictionText::error(a),
                            PredictionText::score(a.score)});
        }
        const Columns cols = fitColumns(headers, rows, 13.0, kWidth - 2 * kMargin);
        y = tableHeader(p, y, cols, headers);
        for (const QStringList& row : rows) y = tableRow(p, y, cols, row, 22.0);
    }
}

void plotsPage(QPainter& p, const SimulationResult& r)
{
    double y = paragraph(p, 60.0, tr("Plots against time"), 18, true);
    const struct {
        plots::Quantity q;
        QString title;
    } charts[] = {{plots::Quantity::Speed, tr("Speed")},
                  {plots::Quantity::SlipSpeed, tr("Slip speed at the cloth")},
                  {plots::Quantity::SpinZ, tr("Side spin ωz")},
                  {plots::Quantity::KineticEnergy, tr("Kinetic energy")}};
    const double h = (kHeight - y - 80.0) / 4.0;
    for (const auto& c : charts) {
        paintChart(p, QRectF(kMargin, y, kWidth - 2 * kMargin, h - 16), c.title,
                   text(plots::unit(c.q)), chartLines(r, c.q), r);
        y += h;
    }
}

}  // namespace

LessonReport::LessonReport(std::shared_ptr<const SimulationResult> result, QString title, QString notes)
    : result_(std::move(result)), title_(std::move(title)), notes_(std::move(notes))
{
}

LessonReport::LessonReport(std::shared_ptr<const SimulationResult> result, const Setup& setup, QStringList noteChanges)
    : result_(std::move(result)), title_(QString::fromStdString(setup.name)), notes_(QString::fromStdString(setup.notes)),
      facts_(shotFacts(setup)), shot_(setup.shot), game_(setup.game), noteChanges_(std::move(noteChanges))
{
}

int LessonReport::keyCollision(const SimulationResult& r)
{
    const ShotOutcome o = shotOutcome(r);
    int first = -1;
    for (int i = 0; i < static_cast<int>(r.events.size()); ++i) {
        const Event& e = r.events[static_cast<std::size_t>(i)];
        if (!isCollision(e.kind)) continue;
        if (first < 0) first = i;
        if (o.firstContact && e.kind == EventKind::BallBall && e.time == o.firstContact->time &&
            (e.balls[0] == o.struckBall || e.balls[1] == o.struckBall))
            return i;
    }
    return first;
}

QStringList LessonReport::eventRow(const SimulationResult& r, int i)
{
    const Event& e = r.events[static_cast<std::size_t>(i)];
    const bool two = e.kind == EventKind::BallBall;
    QString balls = id(r, e.balls[0]);
    if (two) balls += QStringLiteral(", ") + id(r, e.balls[1]);
    QString where;
    if (e.kind == EventKind::BallCushion) where = displayElementName(r.table.cushions[e.cushion].id);
    if (e.kind == EventKind::BallJaw) where = displayElementName(r.table.jaws[e.jaw].id);
    if (e.kind == EventKind::BallPocket) where = displayElementName(r.table.pockets[e.pocket].id);
    QString speeds = QStringLiteral("%1 \u2192 %2").arg(uiNumber(e.before[0].velocity.norm(), 3)).arg(uiNumber(e.after[0].velocity.norm(), 3));
    if (two) speeds += QStringLiteral("; %1 \u2192 %2").arg(uiNumber(e.before[1].velocity.norm(), 3)).arg(uiNumber(e.after[1].velocity.norm(), 3));
    return {eventNumber(i), uiNumber(e.time, 5), displayName(e.kind), balls, where, speeds};
}

int LessonReport::eventPages() const
{
    const int events = result_ ? static_cast<int>(result_->events.size()) : 0;
    return std::max(1, (events + kEventRowsPerPage - 1) / kEventRowsPerPage);
}

void LessonReport::paintPage(QPainter& painter, int page) const
{
    if (!result_) return;
    if (page == 1) {
        // The diagram with its caption (the outcome in a line); the shot's and the physics' tables are
        // the next page's, printed once.
        const ShotDiagram diagram(result_, DiagramText{title_, QString()});
        diagram.paint(painter, QRectF(kMargin, 60, kWidth - 2 * kMargin, kHeight - 140));
        return;
    }
    if (page == 2) return notesAndOutcomePage(painter, *result_, title_, notes_, facts_, noteChanges_, game_);
    int k = page - 2;  // the pages after the notes
    if (!questions_.empty() && k-- == 1) return questionsPage(painter, *result_, questions_);
    if (k == 1) return keyCollisionPage(painter, *result_, shot_);
    const int eventPage = k - 2;  // 0-based among the event pages
    if (eventPage < eventPages()) return cuelab::eventPage(painter, *result_, eventPage * kEventRowsPerPage, kEventRowsPerPage, eventPage == 0);
    plotsPage(painter, *result_);
}

bool LessonReport::write(const QString& path, QString* error, const Progress& progress) const
{
    if (!result_) {
        if (error) *error = QCoreApplication::translate("cuelab", "%1: there is no simulation to report").arg(path);
        return false;
    }
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly)) {
        if (error) *error = QCoreApplication::translate("cuelab", "%1: cannot write the file: %2").arg(path, file.errorString());
        return false;
    }
    const int pages = pageCount();
    bool cancelled = false;
    {
        QPdfWriter pdf(&file);
        pdf.setTitle(title_.isEmpty() ? QCoreApplication::translate("cuelab", "CueLab lesson report") : title_);
        pdf.setCreator(QStringLiteral("CueLab"));
        pdf.setResolution(200);
        pdf.setPageLayout(QPageLayout(QPageSize(QPageSize::A4), QPageLayout::Portrait, QMarginsF(10, 10, 10, 10),
                                      QPageLayout::Millimeter));
        QPainter painter;
        if (!painter.begin(&pdf)) {
            if (error) *error = QCoreApplication::translate("cuelab", "%1: cannot draw the PDF").arg(path);
            file.cancelWriting();
            return false;
        }
        painter.setRenderHint(QPainter::Antialiasing);
        Pages layout(pdf, painter);
        const QString header = QCoreApplication::translate("cuelab", "CueLab lesson report \u2014 %1").arg(title_.isEmpty() ? QCoreApplication::translate("cuelab", "untitled shot") : title_);
        for (int page = 1; page <= pages && !cancelled; ++page) {
            layout.begin(page, pages, header);
            paintPage(painter, page);
            if (progress && !progress(page, pages)) cancelled = true;
        }
        painter.end();
    }
    if (cancelled) {
        file.cancelWriting();
        if (error) *error = QStringLiteral("cancelled");
        return false;
    }
    if (!file.commit()) {
        if (error) *error = QCoreApplication::translate("cuelab", "%1: cannot write the file: %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

}  // namespace cuelab
