#pragma once
// Recording files (CONTRACT.md, Extensions version 2): `cuelab-recording` JSON, or CSV with the
// header `t,ball,x,y` and one row per sample. Read with full checks (core/recording's
// recordingProblem); a file is refused, never half-loaded, with a message naming the file, where
// (a JSON path, or a CSV line) and the problem.

#include "Recording.h"

#include <QByteArray>
#include <QString>

#include <optional>

namespace cuelab::io {

// Parses a `cuelab-recording` JSON document or, when the text begins with the CSV header, a CSV
// recording. A CSV holds no table: it is `csvTable` (default: a 9-ft pool table, as for a setup).
std::optional<Recording> parseRecording(const QByteArray& text, const QString& fileName, QString* error,
                                        const TableSpec& csvTable = {});

// Reads and parses a file; messages name the file by its name without the folder.
std::optional<Recording> loadRecording(const QString& path, QString* error, const TableSpec& csvTable = {});

// The JSON text of a recording (keys in the contract's order, numbers with round-trip precision).
QByteArray serializeRecording(const Recording& recording);

}  // namespace cuelab::io
