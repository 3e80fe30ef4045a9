#pragma once
// "Find shots" in the Analysis dock (issue 42): the strikes that meet the dock's goal most often
// under the odds section's noise, found by core/solve (Solve.h, the same code as `cuelab-cli
// solve`) on background threads with progress and Cancel, listed best first with their odds and
// route. The chosen shot's noise-free paths are offered as a view layer (ghost paths on the table);
// a click on a listed shot loads its strike as one undo step. With "Pick on the table" on, the goal
// is made from clicks (the window's table view reports them, app/window/features/AnalysisFeature.cpp):
// a ball to pot, the pocket it should fall in, and a zone dragged on the cloth where the cue ball
// should stop.

#include "Solve.h"

#include "view/ViewLayer.h"

#include <QGroupBox>

#include <functional>
#include <optional>
#include <utility>
#include <vector>

class QCheckBox;
class QLabel;
class QListWidget;
class QProgressBar;
class QPushButton;
class QSpinBox;

namespace cuelab {

class AnalysisJob;
class Document;

class ShotFinderSection : public QGroupBox {
    Q_OBJECT
public:
    // `goalText`: the dock's goal as typed; `noise`: the odds section's noise model.
    // `setGoalText` replaces the dock's goal (from picks on the table).
    ShotFinderSection(Document* document, std::function<QString()> goalText,
                      std::function<analysis::NoiseModel()> noise, std::function<void(const QString&)> setGoalText,
                      QWidget* parent = nullptr);
    ~ShotFinderSection() override;

    void find();
    void cancel();
    bool loadShot(int row);  // what a click on a listed shot does; false if refused

    // The goal from the table: on while "Pick on the table" is checked.
    bool picking() const;
    void pickBall(int index);                       // the ball to pot (not the struck ball)
    void pickPocket(int index);                     // index into the table's pockets
    void previewZone(const Vec2& a, const Vec2& b); // the zone while it is dragged (m)
    void pickZone(const Vec2& a, const Vec2& b);    // where the cue ball should stop (m)
    // The goal the picks make: "pot:1@pocket-tr,no-scratch,in:cue@X0:Y0:X1:Y1" (parts left out
    // until picked); empty without a ball.
    QString pickedGoal() const;

    // For tests.
    AnalysisJob* job() const { return job_; }
    QListWidget* list() const { return list_; }
    QSpinBox* topBox() const { return top_; }
    QCheckBox* elevationBox() const { return elevation_; }
    QPushButton* pickButton() const { return pick_; }
    QString statusText() const;
    const std::vector<solve::SolvedShot>& shots() const { return shots_; }

    // The paths of the chosen shot (the list's current row) as a layer for the table view; empty
    // when there is none or the list is stale.
    ViewLayer ghostLayer() const;

signals:
    void ghostLayerChanged();

private:
    void setStatus(const QString& text);
    void show(const solve::SolveResult& result);
    void applyPicks();

    Document* document_;
    std::function<QString()> goalText_;
    std::function<analysis::NoiseModel()> noise_;
    std::function<void(const QString&)> setGoalText_;
    AnalysisJob* job_;
    QSpinBox* top_;
    QCheckBox* elevation_;
    QPushButton* find_;
    QPushButton* pick_;
    QListWidget* list_;
    QProgressBar* progress_;
    QPushButton* cancel_;
    QLabel* status_;

    std::vector<solve::SolvedShot> shots_;
    std::vector<std::vector<std::vector<Vec2>>> paths_;  // per shot, per moving ball: its noise-free path
    std::vector<analysis::StrikeKey> vary_;
    bool stale_ = false;    // the setup changed since the shots were found
    bool loading_ = false;  // a listed shot is being loaded (its own setup change)
    int pickedBall_ = -1, pickedPocket_ = -1;
    std::optional<std::pair<Vec2, Vec2>> pickedZone_, zonePreview_;
};

}  // namespace cuelab
