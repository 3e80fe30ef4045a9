#pragma once
// The window's features: each adds its docks, menu actions and connections to a MainWindow through
// the window's extension API (MainWindow::addPanel, MainWindow::menu, the shared document, playback,
// selection and table view). One install function per feature, defined in
// app/window/features/<Name>Feature.cpp, declared here and called from Features.cpp.

#include <QString>

namespace cuelab {

class MainWindow;

// Installs every feature, in a fixed order (the order of their docks in View > Panels).
void installFeatures(MainWindow& window);

void installEditor(MainWindow& window);   // undo history dock, the time box's event numbers (features/EditorFeature.cpp)
void installPlots(MainWindow& window);    // issue 10: the Plots dock
void installOutcome(MainWindow& window);  // issue 10: the Outcome dock and status line
void installExport(MainWindow& window);   // issue 10: File > Export
void installExplain(MainWindow& window);  // features/ExplainFeature.cpp: Explain and Lesson docks, export
void installAim(MainWindow& window);      // features/AimFeature.cpp: View > Overlays > Aim Line and Ghost Ball (issue 22)
void installAnalysis(MainWindow& window);  // features/AnalysisFeature.cpp: the Analysis dock and menu
void installCompare(MainWindow& window);  // features/CompareFeature.cpp
void installRecording(MainWindow& window);  // features/RecordingFeature.cpp: recorded shots (issue 24)
void installPredict(MainWindow& window);  // features/PredictFeature.cpp: predict, then reveal (issue 22)
void installVideo(MainWindow& window);    // features/VideoFeature.cpp: File > Export > Video (issue 22)
void installShotCode(MainWindow& window);  // features/ShotCodeFeature.cpp: Edit > Copy/Paste Shot Code (issue 44)

// Opens a recording file in the window's Recording dock (RecordingFeature.cpp). A recording of balls
// the shot lacks starts a new shot from the recording, after asking when `ask` and the current shot
// is worth keeping (a file, an example, unsaved edits). False when refused (the message is shown).
bool openRecording(MainWindow& window, const QString& path, bool ask);

class VideoExportJob;
struct VideoRequest;
// Starts writing the view as a video behind a progress dialog (VideoFeature.cpp); the job ends with
// VideoExportJob::finished and deletes itself.
VideoExportJob* exportVideo(MainWindow& window, const VideoRequest& request);
// The Export Video dialog (slow motion, frame rate, size) over *request; false when cancelled.
bool askVideoSettings(MainWindow& window, VideoRequest* request);

}  // namespace cuelab
