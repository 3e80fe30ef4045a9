#include "OutcomePanel.h"

#include "i18n/UiNumbers.h"
#include "editor/RunState.h"
#include "layout/ColumnFit.h"

#include "OutcomeLine.h"
#include "explain/ExplainLanguage.h"
#include "i18n/DisplayNames.h"

#include <QEvent>
#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>

namespace cuelab {

namespace {

constexpr int kEventRole = Qt::UserRole + 1;  // event index of a fact row, or -1

QTableWidgetItem* item(const QString& text, const QString& tip = {})
{
    auto* it = new QTableWidgetItem(text);
    it->setFlags(Qt::ItemIsSelectable | Qt::ItemIsEnabled);
    if (!tip.isEmpty()) it->setToolTip(tip);
    return it;
}

int eventIndex(const SimulationResult& r, EventKind kind, int ball, double time)
{
    for (int i = 0; i < static_cast<int>(r.events.size()); ++i) {
        const Event& e = r.events[i];
        if (e.kind == kind && e.time == time && (e.balls[0] == ball || e.balls[1] == ball)) return i;
    }
    return -1;
}

}  // namespace

OutcomePanel::OutcomePanel(QWidget* parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("outcomePanel"));
    header_ = new QLabel(this);
    header_->setWordWrap(true);
    header_->setObjectName(QStringLiteral("outcomeSummary"));
    facts_ = new QTableWidget(0, 2, this);
    facts_->setObjectName(QStringLiteral("outcomeFacts"));
    facts_->setHorizontalHeaderLabels({tr("What"), tr("Outcome")});
    facts_->verticalHeader()->hide();
    facts_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    facts_->setToolTip(tr("Double-click the first contact or a pocketing to go to that event"));
    balls_ = new QTableWidget(0, 4, this);
    balls_->setObjectName(QStringLiteral("outcomeBalls"));
    balls_->setHorizontalHeaderLabels({tr("Ball"), tr("Cushions"), tr("Ends"), tr("x, y (m)")});
    balls_->verticalHeader()->hide();
    balls_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    balls_->setToolTip(tr("Per ball: ball-cushion contacts (jaws included) and where it ends; double-click selects it"));
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(header_);
    layout->addWidget(facts_, 1);
    layout->addWidget(balls_, 2);

    connect(facts_, &QTableWidget::cellDoubleClicked, this, [this](int row, int) {
        const int event = facts_->item(row, 0)->data(kEventRole).toInt();
        if (event >= 0) emit eventActivated(event);
    });
    connect(balls_, &QTableWidget::cellDoubleClicked, this, [this](int row, int) { emit ballActivated(row); });
    facts_->viewport()->installEventFilter(this);
    balls_->viewport()->installEventFilter(this);
    setResult(nullptr);
}

void OutcomePanel::setRecordingResidual(const QString& text)
{
    if (text == recordingResidual_) return;
    recordingResidual_ = text;
    setResult(result_);
}

void OutcomePanel::setResult(std::shared_ptr<const SimulationResult> result)
{
    result_ = std::move(result);
    facts_->setRowCount(0);
    balls_->setRowCount(0);
    verdict_.reset();
    verdictLine_.clear();
    if (!result_) {
        outcome_ = {};
        summary_.clear();
        header_->setText(tr("No simulation yet"));
        return;
    }
    if (!withheld_.isEmpty()) {
        // A lesson's question waits: no outcome, not even the outcome so far ("pocketed: none" would
        // read as an answer).
        outcome_ = {};
        summary_ = tr("%1; the outcome shows after the reveal").arg(withheld_);
        header_->setText(summary_);
        return;
    }
    const SimulationResult& r = *result_;
    outcome_ = shotOutcome(r);
    summary_ = outcomeLine(r, outcome_);
    // The verdict of the game's rules (only for a finished run: a partial one cannot be judged yet).
    if (game_ && r.finished()) verdict_ = rules::judgeShot(r, *game_);
    if (verdict_) {
        verdictLine_ = translated(verdict_->text);
        summary_ = tr("%1. %2").arg(verdictLine_, summary_);
    }
    // A partial run's outcome is the outcome so far, and says where it stopped.
    if (const QString note = RunState::unfinishedNote(r); !note.isEmpty()) summary_ = tr("%1. So far: %2").arg(note, summary_);
    header_->setText(summary_);
    auto id = [&](int ball) { return QString::fromStdString(r.balls.at(static_cast<std::size_t>(ball)).id); };
    auto addFact = [&](const QString& what, const QString& value, int event = -1, const QString& tip = {}) {
        const int row = facts_->rowCount();
        facts_->insertRow(row);
        QTableWidgetItem* w = item(what, tip);
        w->setData(kEventRole, event);
        facts_->setItem(row, 0, w);
        facts_->setItem(row, 1, item(value, tip));
    };
    const ShotOutcome& o = outcome_;
    if (verdict_) {
        const QString where = verdict_->event >= 0 ? tr(" (#%1)").arg(verdict_->event + 1) : QString();
        addFact(verdict_->legal() ? tr("Verdict: legal") : tr("Verdict: foul"), verdictLine_ + where, verdict_->event,
                tr("The rules of the setup's game on this shot; double-click to go to the event that decides it"));
    }
    addFact(tr("Struck ball"), o.struckBall >= 0 ? id(o.struckBall) : tr("none (no shot)"));
    if (o.firstContact)
        addFact(tr("First contact"), tr("%1 at %2 s").arg(id(o.firstContact->ball)).arg(uiNumber(o.firstContact->time, 4)),
                eventIndex(r, EventKind::BallBall, o.struckBall, o.firstContact->time),
                tr("The first ball the struck ball touches, and when (s)"));
    else
        addFact(tr("First contact"), tr("none"));
    addFact(tr("Cushions before it"), QString::number(o.cushionsBeforeFirstContact), -1,
            tr("Ball-cushion contacts of the struck ball before its first contact (jaws included)"));
    if (o.pocketed.empty()) addFact(tr("Pocketed"), tr("none"));
    for (const PocketedBall& p : o.pocketed)
        addFact(tr("Pocketed"),
                tr("%1 in the %2 at %3 s").arg(id(p.ball), displayElementName(r.table.pockets[p.pocket].id)).arg(uiNumber(p.time, 4)),
                eventIndex(r, EventKind::BallPocket, p.ball, p.time));
    addFact(tr("Struck ball pocketed"), o.struckBall >= 0 && o.struckBallPocketed ? tr("yes (a scratch)") : tr("no"));
    if (!recordingResidual_.isEmpty())
        addFact(tr("Against the recording"), recordingResidual_, -1,
                tr("RMSE (cm) of the recorded samples against the simulated balls (the Recording dock has the details)"));

    for (int b = 0; b < static_cast<int>(r.balls.size()); ++b) {
        balls_->insertRow(b);
        const BallState& s = o.finalStates[b];
        balls_->setItem(b, 0, item(id(b)));
        balls_->setItem(b, 1, item(QString::number(o.cushionHits[b])));
        const QString state = s.motion == MotionState::Pocketed
                                  ? tr("in the %1").arg(displayElementName(r.table.pockets[s.pocket].id))
                                  : displayName(s.motion);
        balls_->setItem(b, 2, item(state));
        balls_->setItem(b, 3, item(s.motion == MotionState::Pocketed ? QString()
                                   : QStringLiteral("%1%2%3").arg(uiNumber(s.position.x(), 4), uiListSeparator(), uiNumber(s.position.y(), 4)),
                                   tr("Final position in metres (table frame)")));
    }
    fitColumns();
}

void OutcomePanel::fitColumns()
{
    fitColumnsToWidth(facts_);
    fitColumnsToWidth(balls_);
}

bool OutcomePanel::eventFilter(QObject* watched, QEvent* event)
{
    // The tables' viewports: a narrower dock (or a vertical scroll bar appearing) refits the columns.
    if (event->type() == QEvent::Resize && (watched == facts_->viewport() || watched == balls_->viewport()))
        fitColumnsToWidth(watched == facts_->viewport() ? facts_ : balls_);
    return QWidget::eventFilter(watched, event);
}

}  // namespace cuelab
