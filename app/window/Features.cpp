#include "Features.h"

namespace cuelab {

// One line each: the install function of a feature in app/window/features/.

void installFeatures(MainWindow& window)
{
    installEditor(window);
    installPlots(window);
    installOutcome(window);
    installExport(window);
    installExplain(window);
    installAim(window);
    installAnalysis(window);
    installCompare(window);
    installRecording(window);
    installPredict(window);
    installVideo(window);
    installShotCode(window);
}

}  // namespace cuelab
