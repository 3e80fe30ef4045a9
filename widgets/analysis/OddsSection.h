#pragma once
// The odds section of the Analysis dock (issue 25): how often the current shot meets the goal when
// the player's strike scatters ("goes in 72 % (68–76 %)"), and a map of those odds over two
// parameters. The noise is a preset (FastFiz's defaults, a club player, a professional) or the
// player's own deviations; the work runs on background threads with progress and Cancel; a click on
// a cell of the map loads its shot as one undo step. The numbers come from core/analysis (ShotOdds.h),
// the same code as `cuelab-cli odds` and `sweep --noise`.

#include "Noise.h"
#include "Odds.h"
#include "Sweep.h"

#include <QGroupBox>

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QSpinBox;

namespace cuelab {

class AnalysisJob;
class Document;
class OddsMap;

class OddsSection : public QGroupBox {
    Q_OBJECT
public:
    // `goalText` gives the Analysis dock's goal as the user typed it.
    OddsSection(Document* document, std::function<QString()> goalText, QWidget* parent = nullptr);
    ~OddsSection() override;

    void runOdds();     // the current shot's odds
    void runMap();      // the map of odds
    void cancel();
    bool loadCell(int index);  // what a click on the map does; false if refused

    // The noise the deviation boxes hold (tip offsets in radii).
    analysis::NoiseModel noise() const;
    void setPreset(int index);  // an index of presetBox(): fills the deviation boxes

    // For tests.
    AnalysisJob* job() const { return job_; }
    OddsMap* map() const { return map_; }
    QComboBox* presetBox() const { return preset_; }
    QDoubleSpinBox* sigmaBox(analysis::StrikeKey key) const { return sigma_[static_cast<std::size_t>(key)]; }
    QSpinBox* samplesBox() const { return samples_; }
    QSpinBox* mapCellsBox() const { return cells_; }
    QSpinBox* mapSamplesBox() const { return cellSamples_; }
    QComboBox* xKeyBox() const { return xKey_; }
    QComboBox* yKeyBox() const { return yKey_; }
    QDoubleSpinBox* rangeBox(int axis, int end) const;  // axis 0 = x, 1 = y; end 0 = from, 1 = to
    QString oddsText() const;
    QString statusText() const;
    std::optional<analysis::OddsResult> currentOdds() const { return current_; }

private:
    void onSetupChanged();
    void updateKeys();
    void setStatus(const QString& text);
    std::optional<analysis::SweepSpec> baseSpec(const Setup& setup);
    bool isMapCellOf(const Setup& setup) const;
    double struckBallRadius() const;

    Document* document_;
    std::function<QString()> goalText_;
    AnalysisJob* job_;
    QComboBox* preset_;
    std::array<QDoubleSpinBox*, analysis::kStrikeKeyCount> sigma_{};
    QSpinBox* samples_;
    QPushButton* oddsButton_;
    QLabel* odds_;
    QComboBox* xKey_;
    std::vector<std::string> keyChoices_;  // the keys the x and y boxes hold
    QComboBox* yKey_;
    std::array<QDoubleSpinBox*, 4> range_{};  // x from, x to, y from, y to
    QSpinBox* cells_;
    QSpinBox* cellSamples_;
    QPushButton* mapButton_;
    OddsMap* map_;
    QProgressBar* progress_;
    QPushButton* cancel_;
    QLabel* status_;

    bool settingPreset_ = false;
    std::optional<analysis::OddsResult> current_;
    bool goalIsPot_ = true;
    std::optional<Setup> mapBase_;
    std::optional<analysis::Variation> mapX_, mapY_;
};

}  // namespace cuelab
