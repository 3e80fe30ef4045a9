#pragma once
// File > Export explanation…: the selected event, or every collision of the shot, as a handout in
// HTML or Markdown (by the file's extension), written atomically. The HTML embeds each event's
// figures as inline SVG (the time-of-impact polynomial, the momenta and energies), so the one file
// is the whole handout.

#include "CueStrike.h"
#include "Simulation.h"

#include <QString>

#include <optional>
#include <vector>

namespace cuelab {

// The indices of the shot's collisions (ball-ball, ball-cushion, jaws) and pocketings, in time order.
std::vector<int> collisionEvents(const SimulationResult& result);

// Writes the explanations of `events` to `path` (.md/.markdown: Markdown, otherwise HTML) with
// QSaveFile: on failure the previous file is intact and *error says why.
bool exportExplanations(const QString& path, const SimulationResult& result, const std::optional<CueStrike>& shot,
                        const std::vector<int>& events, const QString& title, QString* error);

}  // namespace cuelab
