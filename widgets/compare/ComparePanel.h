#pragma once
// The Compare panel (issue 9): the shot under another method beside the exact simulation. Choose an
// engine (the 2011 discrete method, Box2D 2.4, or the exact one itself) and its step; the panel
// re-runs it in the background on every change (CompareRunner), draws the error of every ball over
// time with a cursor at the transport's time (CompareChart), lists both collision sequences side by
// side (CollisionTable), says what the engine cannot represent in this shot, and hands the view a
// layer of ghost balls (ghostLayerChanged).

#include "Divergence.h"
#include "Setup.h"
#include "view/ViewLayer.h"

#include <QWidget>

#include <memory>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QProgressBar;
class QSpinBox;
class QTabWidget;
class QTimer;

namespace cuelab {

class CollisionTable;
class CompareChart;
class CompareRunner;

class ComparePanel : public QWidget {
    Q_OBJECT
public:
    explicit ComparePanel(QWidget* parent = nullptr);

    // The shot to compare (the document's setup); re-runs unless it is the same as before.
    void setSetup(const Setup& setup);
    void setTime(double seconds);  // the transport's time: the chart's cursor

    void setEngine(compare::EngineKind kind);
    void setStep(double seconds);   // the engine's step; ignored by the exact engine
    void setSubsteps(int n);
    compare::EngineSettings settings() const;

    // The comparison on show (null before the first run finishes).
    std::shared_ptr<const compare::Comparison> comparison() const;
    bool isRunning() const;
    void waitForIdle();  // tests

    ViewLayer ghosts() const { return ghosts_; }
    bool ghostsEnabled() const;
    CompareChart* chart() const { return chart_; }
    CollisionTable* collisions() const { return table_; }
    QString summaryText() const;
    QString warningsText() const;

signals:
    // The ghosts to draw (an empty layer: none). Emitted after every finished run and when ghosts
    // are switched on or off.
    void ghostLayerChanged(const ViewLayer& layer);
    void timeRequested(double seconds);  // the user picked a collision in the table
    void comparisonChanged();

private:
    void engineChanged();
    void schedule();
    void start();
    void showResult();
    void showFailure(const QString& message);

    QComboBox* engine_;
    QDoubleSpinBox* step_;
    QSpinBox* substeps_;
    QLabel* substepsLabel_;
    QCheckBox* showGhosts_;
    QProgressBar* progress_;
    QLabel* summary_;
    QLabel* warnings_;
    QTabWidget* tabs_;
    CompareChart* chart_;
    CollisionTable* table_;
    CompareRunner* runner_;
    QTimer* debounce_;
    std::optional<Setup> setup_;
    ViewLayer ghosts_;
};

}  // namespace cuelab
