#pragma once
// What the files of MainWindow share (MainWindow.cpp, MainWindowMenus.cpp, MainWindowFiles.cpp).

#include "view/ViewScene.h"

#include <QObject>
#include <QString>

namespace cuelab::window {

inline constexpr int kStatusMessageMs = 6000;  // how long a status message stays

inline QString fileFilter() { return QObject::tr("CueLab setups (*.json);;All files (*)"); }

inline QString overlayKey(Overlay overlay) { return QStringLiteral("overlays/%1").arg(static_cast<int>(overlay)); }

}  // namespace cuelab::window
