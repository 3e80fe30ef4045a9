#pragma once
// Shot codes (CONTRACT.md, Extensions version 3): a whole setup in one line of text, to paste into a
// chat or a link. "cuelab:1:" then the setup file's text, compact and compressed, in URL-safe base64
// (RFC 4648 section 5, no padding). A code goes through the same loader as a file (parseSetup), so it
// is refused for the same reasons with the same messages, and it gives the same simulation bit for bit
// as the setup it was made from: numbers are written with their shortest round-trip digits.
//
// Version 1 leaves out the physics values equal to the table kind's defaults (KindDefaults.h), which
// keeps a 16-ball rack under 600 characters. Those defaults are part of what a version-1 code means:
// tests/io pins them with a code made today; a change of a kind's defaults needs a new code version
// whose reader restores the old values for version 1.

#include "Setup.h"

#include <QString>

#include <optional>

namespace cuelab::io {

inline constexpr int kShotCodeVersion = 1;

// Whether `text` is meant as a shot code (it begins with "cuelab:"): wherever a setup path is taken,
// such text is read as a code (a file whose name begins so is reached as ./cuelab:...).
bool isShotCode(const QString& text);

// The code of a setup (one line, no spaces). The setup must be legal (saveSetup's rule).
QString shotCode(const Setup& setup);

// The code of a setup file's text taken as it is (no defaults left out, nothing checked): for tests
// of the reader's refusals, which need codes of texts no setup would give.
QString shotCodeOfText(const QByteArray& json);

// Reads a code, as parseSetup reads a file's text; messages begin with "shot code".
std::optional<Setup> parseShotCode(const QString& code, QString* error);

}  // namespace cuelab::io
