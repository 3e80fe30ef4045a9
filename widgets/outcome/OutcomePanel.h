#pragma once
// The Outcome panel: what the shot did, from core/outcome. The struck ball, the first contact, the
// cushions before it, the pocketed balls (pocket, time), and per ball its cushion contacts and where
// it ended. Double-clicking the first contact or a pocketing selects that event.

#include "ShotOutcome.h"
#include "Simulation.h"

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
    QString summary_;
    QString recordingResidual_;
    QLabel* header_ = nullptr;
    QTableWidget* facts_ = nullptr;
    QTableWidget* balls_ = nullptr;
};

}  // namespace cuelab
