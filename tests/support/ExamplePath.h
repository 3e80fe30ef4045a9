#pragma once
// The path of a bundled example (resources/examples), for the suites that open it by name.

#include <QString>

inline QString examplePath(const QString& name) { return QStringLiteral(CUELAB_SOURCE_DIR "/resources/examples/") + name; }
inline QString examplePath(const char* name) { return examplePath(QString::fromUtf8(name)); }
