#pragma once
// A bundled example loaded as a setup. A file that does not load stops the suite with the loader's
// message: the examples are part of the product, so that is a failure, never a skip.

#include "ExamplePath.h"
#include "SetupFile.h"

#include <QtGlobal>

inline cuelab::Setup loadExample(const QString& name)
{
    QString error;
    const std::optional<cuelab::Setup> setup = cuelab::io::loadSetup(examplePath(name), &error);
    if (!setup) qFatal("%s", qPrintable(error));
    return *setup;
}
inline cuelab::Setup loadExample(const char* name) { return loadExample(QString::fromUtf8(name)); }
