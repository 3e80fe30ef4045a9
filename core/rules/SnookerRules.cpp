// Snooker (WPBSA rules as far as one shot can judge them; docs/rules.md).

#include "Judging.h"

#include <algorithm>
#include <array>
#include <string_view>

namespace cuelab::rules {

namespace {

bool isRed(const std::string& id) { return id.size() > 4 && id.compare(0, 4, "red-") == 0; }

// WPBSA values: red 1, yellow 2, green 3, brown 4, blue 5, pink 6, black 7; the cue ball 0.
int value(const std::string& id)
{
    if (isRed(id)) return 1;
    constexpr std::array<std::string_view, 6> colours{"yellow", "green", "brown", "blue", "pink", "black"};
    for (std::size_t i = 0; i < colours.size(); ++i)
        if (colours[i] == id) return static_cast<int>(i) + 2;
    return 0;
}

bool isColour(const std::string& id) { return value(id) >= 2; }

// The id of a named colour on (yellow ... black), empty for red and for any colour.
std::string namedColour(SnookerOn on)
{
    switch (on) {
    case SnookerOn::Red:
    case SnookerOn::Colour: return {};
    default: return std::string(toString(on));
    }
}

}  // namespace

Verdict judgeSnooker(const ShotFacts& f, const GameSpec& game)
{
    Verdict v;
    Fouls fouls;
    const SnookerOn on = game.on.value_or(SnookerOn::Red);
    bool redsOnTable = false;
    for (int b = 0; b < f.ballCount(); ++b) redsOnTable = redsOnTable || isRed(f.id(b));

    // The colour on: the named one, or with any colour on the one the cue ball meets first (taken as
    // the striker's nomination); empty when no colour is nominated that way.
    std::string colourOn = namedColour(on);
    if (on == SnookerOn::Colour && f.firstContact >= 0 && isColour(f.id(f.firstContact))) colourOn = f.id(f.firstContact);
    const auto isOn = [&](int b) {
        const std::string& id = f.id(b);
        if (on == SnookerOn::Red) return isRed(id);
        return !colourOn.empty() && id == colourOn;
    };
    // The value of the ball on for a foul: a red 1, the colour on its own; any colour with none
    // nominated 7 (WPBSA 3.12: a foul before a nomination).
    const int onValue = on == SnookerOn::Red ? 1 : colourOn.empty() ? 7 : value(colourOn);
    const Text onText = on == SnookerOn::Red ? Text::tr("a red") : colourOn.empty() ? Text::tr("a colour") : Text(colourOn);

    cueBallFouls(f, isOn, onText, fouls);
    for (const BallGone& g : f.pocketed)
        if (g.ball != f.struck && !isOn(g.ball))
            fouls.add(FoulRule::WrongBallPocketed, g.event,
                      Text::tr("%1 was potted, and %2 was on").arg(ballText(f, g.ball)).arg(onText));
    v.foul = fouls.first();

    if (v.foul) {
        // The penalty: the value of the ball on, of the ball first hit and of every ball potted or
        // forced off the table wrongly, whichever is highest, and at least 4 (WPBSA 3.13).
        int penalty = std::max(4, onValue);
        if (f.firstContact >= 0) penalty = std::max(penalty, value(f.id(f.firstContact)));
        for (const auto* list : {&f.pocketed, &f.offTable})
            for (const BallGone& g : *list)
                if (g.ball != f.struck && (!isOn(g.ball) || list == &f.offTable)) penalty = std::max(penalty, value(f.id(g.ball)));
        v.foulPoints = penalty;
        // Colours potted or forced off on a foul are respotted; reds stay off (WPBSA 3.4, 3.14).
        for (const auto* list : {&f.pocketed, &f.offTable})
            for (const BallGone& g : *list)
                if (isColour(f.id(g.ball))) v.respotted.push_back(g.ball);
        v.ballInHand = f.gone(f.struck);  // in hand in the D
        v.text = Text::tr("foul (%1): %2; %3 points to the opponent")
                     .arg(Text(std::string(toString(v.foul->rule))))
                     .arg(v.foul->text)
                     .arg(Text(std::to_string(penalty)));
        return v;
    }

    for (const BallGone& g : f.pocketed) {
        v.scored.push_back(g.ball);
        v.points += value(f.id(g.ball));
        v.event = g.event;
        // A colour potted while reds remain (or just after the last red) is respotted; in the
        // clearing of the colours it stays down.
        if (isColour(f.id(g.ball)) && (redsOnTable || on == SnookerOn::Colour)) v.respotted.push_back(g.ball);
    }
    // Reds forced off the table on a legal shot: none can be, that is a foul; nothing to do here.
    v.continues = !v.scored.empty();
    if (v.continues) {
        std::vector<Text> ids;
        for (const int b : v.scored) ids.push_back(ballText(f, b));
        v.text = Text::tr("legal: %1 potted (+%2); the striker plays on")
                     .arg(Text::join(std::move(ids), ", "))
                     .arg(Text(std::to_string(v.points)));
    } else {
        v.text = Text::tr("legal: nothing potted; the turn passes");
    }
    return v;
}

}  // namespace cuelab::rules
