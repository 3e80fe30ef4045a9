#pragma once
// Setup files (CONTRACT.md, version 1): load with full validation, save atomically.
// Uses QtCore's JSON; the physics it fills in (cuelab_physics) stays Qt-free.

#include "Setup.h"

#include <QByteArray>
#include <QString>

#include <optional>

namespace cuelab::io {

// Parses and validates a setup. `fileName` is used only in messages ("rack.json: balls[3].position:
// overlaps ball \"7\" by 2.1 mm"). On refusal returns nullopt and sets *error; never half-loads.
std::optional<Setup> parseSetup(const QByteArray& json, const QString& fileName, QString* error);

// Reads and parses a file; messages name the file by its name without the folder. A shot code
// ("cuelab:1:...", ShotCode.h) in place of the path is read as the setup it holds.
std::optional<Setup> loadSetup(const QString& path, QString* error);

// The JSON text of a setup (same format, keys in CONTRACT.md's order, numbers with round-trip
// precision). Physics values are always written; ball velocity, spin, radius and mass only when
// they differ from zero or the table's ball.
QByteArray serializeSetup(const Setup& setup);

// Writes atomically (QSaveFile): on failure the previous file is intact and *error says why.
// A setup that would not load again (parseSetup refuses its text) is not written at all.
bool saveSetup(const Setup& setup, const QString& path, QString* error);

}  // namespace cuelab::io
