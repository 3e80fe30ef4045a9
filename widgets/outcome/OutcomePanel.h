#pragma once
// The Outcome panel: what the shot did, from core/outcome. The struck ball, the first contact, the
// cushions before it, the pocketed balls (pocket, time), and per ball its cushion contacts and where
// it ended. Double-clicking the first contact or a pocketing selects that event. With a game (the
// setup's), the verdict of its rules comes first (issue 43): legal or the foul and why, in one line,
// linked to the event that decides it.

#include "ShotOutcome.h"
#include "Simulation.h"
#include "Verdict.h"

#include <QWidget>

#include <memory>

class QLabel;
class QTableWidget;

namespace cuelab {

class OutcomePanel : public QWidget {
    Q_OBJECT
public:
    explicit OutcomePanel(QWidget* parent = nullptr);

    void setResult(std::shared_ptr<const SimulationResult> result);
    // The game whose rules judge the shot (none: no verdict); takes effect at the next setResult.
    void setGame(const std::optional<GameSpec>& game) { game_ = game; }
    // A lesson's question waits for its reveal (Document::setHorizon): the panel gives `note`
    // (RunState::withheldNote) and no outcome, no verdict. Empty: the whole run. Takes effect at the
    // next setResult.
    void setWithheld(const QString& note) { withheld_ = note; }
    const std::optional<rules::Verdict>& verdict() const { return verdict_; }
    QString verdictLine() const { return verdictLine_; }  // the verdict in the window's language; empty: none
    const ShotOutcome& outcome() const { return outcome_; }
    QString summary() const { return summary_; }  // the status bar's line
    // The residual against an open recording (issue 24), a row of the facts; empty: no row.
    void setRecordingResidual(const QString& text);
    QTableWidget* factsTable() const { return facts_; }
    QTableWidget* ballsTable() const { return balls_; }

signals:
    void eventActivated(int index);  // the first contact's or a pocketing's event
    void ballActivated(int index);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void fitColumns();  // to the dock's width, wrapping instead of scrolling sideways (ColumnFit.h)

    std::shared_ptr<const SimulationResult> result_;
    ShotOutcome outcome_;
    std::optional<GameSpec> game_;
    std::optional<rules::Verdict> verdict_;
    QString verdictLine_;
    QString summary_;
    QString recordingResidual_;
    QString withheld_;
    QLabel* header_ = nullptr;
    QTableWidget* facts_ = nullptr;
    QTableWidget* balls_ = nullptr;
};

}  // namespace cuelab
