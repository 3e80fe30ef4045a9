#pragma once
// QJsonDocument keeps the last of two equal keys in an object and says nothing. A setup file with
// "radius" twice in one ball is a mistake like a typo, so the loader looks for duplicates itself.

#include "SetupProblem.h"

#include <QByteArray>

#include <optional>

namespace cuelab::io {

// The first key that appears twice in one object of `json`, which must be valid JSON (parse it
// first): its JSON path ("balls[1].radius") and where the first one stands.
std::optional<SetupProblem> findDuplicateKey(const QByteArray& json);

}  // namespace cuelab::io
