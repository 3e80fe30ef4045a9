#include "LegalGame.h"

#include "LegalGeometry.h"

#include <algorithm>
#include <array>
#include <string_view>

namespace cuelab {

using legal::ballPath;
using legal::quoted;

namespace {

constexpr std::array<std::string_view, 6> kColours{"yellow", "green", "brown", "blue", "pink", "black"};

bool isPool(GameRules rules)
{
    return rules == GameRules::EightBall || rules == GameRules::NineBall || rules == GameRules::TenBall;
}

int rackSize(GameRules rules)
{
    switch (rules) {
    case GameRules::EightBall: return 15;
    case GameRules::NineBall: return 9;
    case GameRules::TenBall: return 10;
    default: return 0;
    }
}

// The number of a pool ball id ("1" ... "15" written plainly), or 0.
int poolNumber(const std::string& id)
{
    if (id.empty() || id.size() > 2 || id[0] == '0') return 0;
    int n = 0;
    for (const char c : id) {
        if (c < '0' || c > '9') return 0;
        n = n * 10 + (c - '0');
    }
    return n;
}

bool fitsSnooker(const std::string& id)
{
    if (id == "cue") return true;
    if (id.size() > 4 && id.compare(0, 4, "red-") == 0) return true;
    return std::find(kColours.begin(), kColours.end(), id) != kColours.end();
}

// What the ids of the game are, for a message.
std::string expectedIds(GameRules rules)
{
    if (isPool(rules)) return "cue and 1 to " + std::to_string(rackSize(rules));
    return "cue, red-<n>, yellow, green, brown, blue, pink and black";
}

}  // namespace

std::vector<SetupProblem> gameProblems(const Setup& setup)
{
    std::vector<SetupProblem> out;
    if (!setup.game) return out;
    const GameSpec& game = *setup.game;
    const std::string rules(toString(game.rules));
    if (game.group && game.rules != GameRules::EightBall)
        out.push_back({"game.group", {}, -1, "a group belongs to 8-ball, not to " + rules});
    if (game.on && game.rules != GameRules::Snooker)
        out.push_back({"game.on", {}, -1, "a ball on belongs to snooker, not to " + rules});
    if (game.breakShot && !isPool(game.rules))
        out.push_back({"game.break", {}, -1, "a break belongs to 8-, 9- and 10-ball, not to " + rules});
    if (!game.nominated.empty()) {
        bool found = false;
        if (legal::tableSpecUsable(setup.table)) {
            const Table table = makeTable(setup.table);
            found = std::any_of(table.pockets.begin(), table.pockets.end(),
                                [&](const Pocket& p) { return p.id == game.nominated; });
        }
        if (!found) out.push_back({"game.nominated", {}, -1, "the table has no pocket " + quoted(game.nominated)});
    }

    if (game.rules == GameRules::ThreeCushion) {
        if (setup.balls.size() != 3)
            out.push_back({"balls", {}, -1,
                           "three-cushion is played with three balls; the setup has " + std::to_string(setup.balls.size())});
        return out;
    }
    if (setup.shot && setup.shot->ball != "cue")
        out.push_back({"shot.ball", {}, -1, rules + " is played with the ball \"cue\", not " + quoted(setup.shot->ball)});
    for (std::size_t i = 0; i < setup.balls.size(); ++i) {
        const std::string& id = setup.balls[i].id;
        const int index = static_cast<int>(i);
        const bool fits = isPool(game.rules) ? id == "cue" || (poolNumber(id) >= 1 && poolNumber(id) <= rackSize(game.rules))
                                             : fitsSnooker(id);
        if (!fits)
            out.push_back({ballPath(index, "id"), id, index,
                           "ball " + quoted(id) + " is not a ball of " + rules + " (its balls are " + expectedIds(game.rules) + ")"});
    }
    return out;
}

}  // namespace cuelab
