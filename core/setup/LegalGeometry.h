#pragma once
// The geometric rules of a legal setup, as measures shared by the validator (LegalSetup) and the
// search for a legal spot (LegalPlacement), so that both agree to the last bit on where a ball may be.

#include "LegalSetup.h"

#include "Table.h"

#include <optional>
#include <string>

namespace cuelab::legal {

// Distance from p to the closest point of the segment [a, b].
double distanceToSegment(const Vec2& p, const Vec2& a, const Vec2& b);

// How a ball of radius r centred at p stands on the table, ignoring the other balls: the smallest
// free margin to each kind of obstacle (positive = clear by this much, negative = intrudes).
struct TableMargins {
    double surface = 0.0;  // m, to the edges of the playing surface [0, length] x [0, width] (centre)
    double pocket = 0.0;   // m, of the centre outside the nearest pocket circle
    double contact = 0.0;  // m, the ball's gap to the nearest cushion nose or jaw tip
    std::string pocketId;  // the pocket of `pocket`
    std::string contactId; // "cushion \"rail-b-left\"" or "jaw \"jaw-b-left\"" of `contact`
};
TableMargins tableMargins(const Table& table, double radius, const Vec2& p);

// A table too short or too narrow for its pockets turns a rail inside out: its problem, if any.
std::optional<SetupProblem> railsProblem(const Table& table);

// The problems of ball `index` against the table alone (cushion height, surface, pockets, cushions,
// jaws): at most one, the first in that order.
std::optional<SetupProblem> tableProblem(const Table& table, const Ball& ball, int index);

// The problem of ball `index` overlapping ball `other` (index `otherIndex`), if they overlap by more
// than kOverlapTolerance.
std::optional<SetupProblem> overlapProblem(const Ball& ball, int index, const Ball& other);

// Whether the table's own numbers allow building it (lengths finite, positive, within SetupBounds):
// otherwise there is no geometry to check against.
bool tableSpecUsable(const TableSpec& spec);

// "balls[2].position"
std::string ballPath(int index, const char* key);
// "\"cue\""
std::string quoted(const std::string& text);

}  // namespace cuelab::legal
