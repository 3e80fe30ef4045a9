#pragma once
// The Analysis dock (issue 11): which aim, speed, elevation and tip offsets make the current shot,
// and by how much one can miss. A goal (core/analysis/Goal.h) says what "make" means; 1-D
// tolerance bars give the success window of heading, speed, elevation, side and height around the
// current values; a 2-D map (the tip-offset disk, or any two numeric keys) shows the outcome of
// every cell, and a click on a cell loads its shot into the editor as one undo step. The work runs
// on background threads (AnalysisJob), results stream in, Cancel stops it, and results are dropped
// when the setup changes (a map stays while its own cells are loaded).

#include "Map.h"
#include "Tolerance.h"

#include <QWidget>

#include <optional>
#include <string>
#include <vector>

class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QTableWidget;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QSpinBox;
class QTabWidget;

namespace cuelab {

class AnalysisJob;
class Document;
class OutcomeMap;
class ToleranceBar;

class AnalysisPanel : public QWidget {
    Q_OBJECT
public:
    explicit AnalysisPanel(Document* document, QWidget* parent = nullptr);
    ~AnalysisPanel() override;

    // Starts the scans / the map for the current setup (what the buttons do).
    void runTolerance();
    void runMap();
    void cancel();

    // For tests and the window.
    AnalysisJob* job() const { return job_; }
    OutcomeMap* map() const { return map_; }
    const std::vector<ToleranceBar*>& bars() const { return bars_; }
    // The windows as numbers: per parameter from, to, width, and what lies beyond each end.
    QTableWidget* toleranceTable() const { return toleranceTable_; }
    QLineEdit* goalEdit() const { return goal_; }
    QComboBox* mapMode() const { return mode_; }
    QSpinBox* mapCells() const { return cells_; }
    QString statusText() const;
    // Loads cell `index` of the map into the editor (what a click does); false if refused.
    bool loadCell(int index);

    enum MapMode { TipOffsetDisk = 0, TwoParameters = 1 };
    // The dock's tabs, in order.
    enum Section { TolerancePage = 0, MapPage = 1, OddsPage = 2, FinderPage = 3 };
    QTabWidget* sections() const { return sections_; }
    void showSection(Section section);

private:
    void onSetupChanged();
    void onResultChanged();
    void updateAxisChoices();
    void setStatus(const QString& text);
    void fillToleranceTable();  // from the bars' scans
    // The goal of the line edit for the current setup; nullopt (and a message shown) if it is wrong.
    std::optional<analysis::ResolvedGoal> currentGoal();
    QString defaultGoal() const;
    analysis::SweepSpec baseSpec(const analysis::ResolvedGoal& goal) const;
    bool isMapCellOf(const Setup& setup) const;

    Document* document_;
    AnalysisJob* job_;
    QLineEdit* goal_;
    QPushButton* goalFromShot_;
    QPushButton* scan_;
    std::vector<ToleranceBar*> bars_;
    QLabel* toleranceGoal_;
    QTableWidget* toleranceTable_;
    QFormLayout* mapForm_ = nullptr;
    QComboBox* mode_;
    QComboBox* xKey_;
    std::vector<std::string> keyChoices_;  // the keys the x and y boxes hold
    QComboBox* yKey_;
    QDoubleSpinBox* xFrom_;
    QDoubleSpinBox* xTo_;
    QDoubleSpinBox* yFrom_;
    QDoubleSpinBox* yTo_;
    QSpinBox* cells_;
    QPushButton* mapButton_;
    OutcomeMap* map_;
    QProgressBar* progress_;
    QPushButton* cancel_;
    QLabel* status_;
    QTabWidget* sections_ = nullptr;

    bool goalEdited_ = false;  // the user typed a goal: keep it across edits of the shot
    // The map's setup and axes: a setup equal to it but for the two mapped values is one of its cells.
    std::optional<Setup> mapBase_;
    std::optional<analysis::Variation> mapX_, mapY_;
    QString mapGoalText_;
    bool loadingCell_ = false;
};

}  // namespace cuelab
