#pragma once
// The Recording dock (issue 24): a recorded shot (core/recording) against the simulation of the
// current setup. It shows the recording's balls and length, the residual (RMSE over the struck ball
// and over every ball, per ball), a plot of each sample's distance to the simulated ball over time,
// and fits the strike to the recording (core/fit: the same fitStrike as `cuelab-cli fit`) on a worker
// thread with progress and Cancel; the fitted strike is one undoable edit of the document. Calibrate
// Cloth fits the cloth's frictions (physics.mu_roll, physics.mu_slide) over every recording opened in
// this session (core/fit's calibrate, as `cuelab-cli calibrate`), each recording with its own strike:
// the current one from the document's setup, the others from the setup each recording suggests; the
// calibrated frictions and the current recording's strike are one undoable edit. The residual comes
// from core/recording's residual(), recomputed whenever the result changes.

#include "Recording.h"
#include "Residual.h"
#include "Simulation.h"

#include <QByteArray>
#include <QColor>
#include <QWidget>

#include <atomic>
#include <memory>
#include <string>
#include <vector>
#include <optional>
#include <stop_token>

class QAction;
class QLabel;
class QProgressBar;
class QPushButton;
class QTableWidget;
template <typename T> class QFutureWatcher;

namespace cuelab {

class Document;
class ResidualChart;

namespace fit {
struct FitResult;
}

class RecordingPanel : public QWidget {
    Q_OBJECT
public:
    explicit RecordingPanel(Document* document, QWidget* parent = nullptr);
    ~RecordingPanel() override;

    // The recording shown (and added to the session's recordings when new); nullopt closes them all.
    void setRecording(std::optional<Recording> recording);
    int recordingCount() const { return static_cast<int>(session_.size()); }
    const std::optional<Recording>& recording() const { return recording_; }
    // Of the current result against the recording, samples kept (none without both).
    const std::optional<Residual>& residual() const { return residual_; }
    // "struck ball 3.2 cm, every ball 5.1 cm" (empty without a residual): the Outcome dock's line.
    QString summary() const;
    // The colour of a recorded ball: its simulated path's colour (lifted for contrast with the cloth),
    // so that its dots and its path in the view are one colour. viewColour: in the view's (linear)
    // terms, for a view layer; chartColour: the same hue for the residual plot's white ground.
    static QColor viewColour(TableKind kind, const std::string& id);
    static QColor chartColour(TableKind kind, const std::string& id);
    // The residual sample by sample (core/recording residualCsv), "" without one.
    QByteArray residualCsv() const;
    QAction* exportResidualsAction() const { return exportResiduals_; }
    QAction* exportSetupAction() const { return exportSetup_; }

    void fitStrike();    // starts the fit (no-op while one runs)
    void calibrateCloth();  // starts the calibration over the session's recordings
    void cancelFit();
    bool isFitting() const;

    QTableWidget* ballsTable() const { return balls_; }
    QPushButton* fitButton() const { return fit_; }
    QPushButton* calibrateButton() const { return calibrate_; }
    static std::vector<std::string> calibratedKeys() { return {"physics.mu_roll", "physics.mu_slide"}; }

signals:
    void recordingChanged();  // opened or closed
    void residualChanged();
    void fitFinished(bool applied, const QString& message);

private:
    void refresh();  // the residual and everything that shows it
    void fitDone();
    void startProgress(const std::shared_ptr<std::atomic_int>& done, const std::shared_ptr<std::atomic_int>& total);

    Document* document_;
    std::optional<Recording> recording_;
    std::vector<Recording> session_;  // every recording opened, the shown one included
    std::optional<Residual> residual_;
    QLabel* header_;
    QLabel* rmse_;
    QTableWidget* balls_;
    ResidualChart* chart_;
    QPushButton* fit_;
    QPushButton* calibrate_;
    QPushButton* cancel_;
    QAction* exportResiduals_;
    QAction* exportSetup_;
    QProgressBar* progress_;
    QFutureWatcher<std::shared_ptr<fit::FitResult>>* watcher_;  // a strike fit or a calibration
    std::unique_ptr<std::stop_source> stop_;
};

}  // namespace cuelab
