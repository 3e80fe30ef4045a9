// FIRST CUT: the offscreen renderer lands with the table renderer.
#include "Screenshot.h"

namespace cuelab {

bool renderSceneToImage(const ViewScene&, double, CameraPreset, QSize, QImage*, QString* error)
{
    if (error) *error = QStringLiteral("Screenshots are not available in this build yet.");
    return false;
}

}  // namespace cuelab
