#pragma once
// Where a dialog that writes a file (File > Export, the video, Explain's export) starts (issue 44):
// the folder the last export went to; else the document's own folder when it is the user's (not a
// bundled example's folder, which is read-only once installed, and writable); else the user's
// documents folder; else the home folder.

#include <QString>

namespace cuelab {

class Document;

namespace window {

// The path to propose: that folder and `fileName`.
QString exportStartPath(const Document& document, const QString& fileName);
// Remembers the folder of a file just chosen in such a dialog.
void rememberExportFolder(const QString& path);

}  // namespace window
}  // namespace cuelab
