#include "Goal.h"

#include "Override.h"
#include "Verdict.h"

#include <array>
#include <cmath>
#include <utility>

namespace cuelab::analysis {

namespace {

std::vector<std::string_view> split(std::string_view text, char separator)
{
    std::vector<std::string_view> parts;
    std::size_t start = 0;
    while (true) {
        const std::size_t end = text.find(separator, start);
        parts.push_back(text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
        if (end == std::string_view::npos) break;
        start = end + 1;
    }
    return parts;
}

std::string quoted(std::string_view text) { return "\"" + std::string(text) + "\""; }

std::variant<GoalTerm, std::string> parseTerm(std::string_view text)
{
    GoalTerm term;
    const std::string original(text);
    if (!text.empty() && text.front() == '!') {
        term.negated = true;
        text.remove_prefix(1);
    }
    const auto bad = [&](const std::string& why) { return "goal term " + quoted(original) + ": " + why; };
    const std::size_t colon = text.find(':');
    const std::string_view head = text.substr(0, colon);
    const std::string_view rest = colon == std::string_view::npos ? std::string_view() : text.substr(colon + 1);
    for (const auto& [name, kind] : {std::pair{std::string_view("no-scratch"), GoalTerm::Kind::StruckBallUp},
                                      std::pair{std::string_view("legal"), GoalTerm::Kind::Legal},
                                      std::pair{std::string_view("scores"), GoalTerm::Kind::Scores},
                                      std::pair{std::string_view("point"), GoalTerm::Kind::Point}}) {
        if (head != name) continue;
        if (colon != std::string_view::npos) return bad(std::string(name) + " takes no argument");
        term.kind = kind;
        return term;
    }
    if (colon == std::string_view::npos || rest.empty())
        return bad("expected pot:BALL[@POCKET], first:BALL, no-scratch, in:BALL@X0:Y0:X1:Y1, legal, scores or point");
    if (head == "pot") {
        term.kind = GoalTerm::Kind::Pocketed;
        const std::size_t at = rest.find('@');
        term.ball = std::string(rest.substr(0, at));
        if (at != std::string_view::npos) {
            term.pocket = std::string(rest.substr(at + 1));
            if (term.pocket.empty()) return bad("no pocket after '@'");
        }
        if (term.ball.empty()) return bad("no ball id");
        return term;
    }
    if (head == "first") {
        term.kind = GoalTerm::Kind::FirstContact;
        term.ball = std::string(rest);
        return term;
    }
    if (head == "in") {
        term.kind = GoalTerm::Kind::EndsInRegion;
        const std::size_t at = rest.rfind('@');
        if (at == std::string_view::npos || at == 0) return bad("expected in:BALL@X0:Y0:X1:Y1");
        term.ball = std::string(rest.substr(0, at));
        const std::vector<std::string_view> numbers = split(rest.substr(at + 1), ':');
        if (numbers.size() != 4) return bad("the region needs four numbers X0:Y0:X1:Y1 (m)");
        std::array<double, 4> v{};
        for (std::size_t i = 0; i < 4; ++i) {
            const auto x = parseNumber(numbers[i]);
            if (!x) return bad("not a number: " + quoted(numbers[i]));
            v[i] = *x;
        }
        term.region = {v[0], v[1], v[2], v[3]};
        return term;
    }
    if (head == "cushions") {
        term.kind = GoalTerm::Kind::CushionHits;
        std::size_t op = rest.find_first_of("<>=");
        if (op == std::string_view::npos || op == 0) return bad("expected cushions:BALL=N, cushions:BALL<=N or cushions:BALL>=N");
        term.ball = std::string(rest.substr(0, op));
        std::string_view number = rest.substr(op);
        if (number.substr(0, 2) == "<=") term.compare = GoalTerm::Compare::AtMost, number.remove_prefix(2);
        else if (number.substr(0, 2) == ">=") term.compare = GoalTerm::Compare::AtLeast, number.remove_prefix(2);
        else if (number.front() == '=') term.compare = GoalTerm::Compare::Equal, number.remove_prefix(1);
        else return bad("expected =N, <=N or >=N after the ball");
        const auto n = parseNumber(number);
        if (!n || *n < 0 || *n != std::floor(*n) || *n > 1e6) return bad("not a whole number of cushions: " + quoted(number));
        term.count = static_cast<int>(*n);
        return term;
    }
    return bad("unknown kind " + quoted(head) + " (expected pot, first, no-scratch, in, cushions, legal, scores or point)");
}

const char* compareText(GoalTerm::Compare c)
{
    return c == GoalTerm::Compare::AtMost ? "<=" : c == GoalTerm::Compare::AtLeast ? ">=" : "=";
}

std::string numberText(double x)
{
    std::string s = std::to_string(x);
    while (s.size() > 1 && s.back() == '0') s.pop_back();
    if (!s.empty() && s.back() == '.') s.pop_back();
    return s;
}

}  // namespace

std::variant<Goal, std::string> parseGoal(std::string_view text)
{
    Goal goal;
    if (text.empty()) return goal;
    for (std::string_view part : split(text, ',')) {
        while (!part.empty() && part.front() == ' ') part.remove_prefix(1);
        while (!part.empty() && part.back() == ' ') part.remove_suffix(1);
        if (part.empty()) return std::string("goal: an empty term (two commas in a row?)");
        auto term = parseTerm(part);
        if (auto* error = std::get_if<std::string>(&term)) return *error;
        goal.terms.push_back(std::get<GoalTerm>(std::move(term)));
    }
    return goal;
}

std::string goalText(const Goal& goal)
{
    std::string out;
    for (const GoalTerm& t : goal.terms) {
        if (!out.empty()) out += ',';
        if (t.negated) out += '!';
        switch (t.kind) {
        case GoalTerm::Kind::Pocketed: out += "pot:" + t.ball + (t.pocket.empty() ? "" : "@" + t.pocket); break;
        case GoalTerm::Kind::FirstContact: out += "first:" + t.ball; break;
        case GoalTerm::Kind::StruckBallUp: out += "no-scratch"; break;
        case GoalTerm::Kind::EndsInRegion:
            out += "in:" + t.ball + "@" + numberText(t.region.x0) + ":" + numberText(t.region.y0) + ":" +
                   numberText(t.region.x1) + ":" + numberText(t.region.y1);
            break;
        case GoalTerm::Kind::CushionHits:
            out += "cushions:" + t.ball + compareText(t.compare) + std::to_string(t.count);
            break;
        case GoalTerm::Kind::Legal: out += "legal"; break;
        case GoalTerm::Kind::Scores: out += "scores"; break;
        case GoalTerm::Kind::Point: out += "point"; break;
        }
    }
    return out;
}

std::string describeGoal(const Goal& goal)
{
    if (goal.empty()) return "any shot";
    std::string out;
    for (const GoalTerm& t : goal.terms) {
        if (!out.empty()) out += ", ";
        const std::string no = t.negated ? "not " : "";
        switch (t.kind) {
        case GoalTerm::Kind::Pocketed:
            out += no + "pot " + t.ball + (t.pocket.empty() ? "" : " in " + t.pocket);
            break;
        case GoalTerm::Kind::FirstContact: out += no + "hit " + t.ball + " first"; break;
        case GoalTerm::Kind::StruckBallUp: out += t.negated ? "scratch" : "no scratch"; break;
        case GoalTerm::Kind::EndsInRegion: out += t.ball + (t.negated ? " ends outside" : " ends inside") + " the region"; break;
        case GoalTerm::Kind::CushionHits:
            out += no + t.ball + " touches " +
                   (t.compare == GoalTerm::Compare::AtMost ? "at most " : t.compare == GoalTerm::Compare::AtLeast ? "at least " : "") +
                   std::to_string(t.count) + (t.count == 1 ? " cushion" : " cushions");
            break;
        case GoalTerm::Kind::Legal: out += t.negated ? "a foul" : "a legal shot"; break;
        case GoalTerm::Kind::Scores: out += t.negated ? "the turn passes" : "the striker plays on"; break;
        case GoalTerm::Kind::Point: out += t.negated ? "no point" : "a three-cushion point"; break;
        }
    }
    return out;
}

std::optional<ResolvedGoal> ResolvedGoal::resolve(const Goal& goal, const Setup& setup, std::string* error)
{
    const Table table = makeTable(setup.table);
    ResolvedGoal resolved;
    for (const GoalTerm& t : goal.terms) {
        Term term{t.kind, t.negated, -1, -1, t.region, t.count, t.compare};
        const bool ofRules = t.kind == GoalTerm::Kind::Legal || t.kind == GoalTerm::Kind::Scores || t.kind == GoalTerm::Kind::Point;
        if (ofRules) {
            const std::string name = t.kind == GoalTerm::Kind::Legal ? "legal" : t.kind == GoalTerm::Kind::Scores ? "scores" : "point";
            if (!setup.game) {
                if (error)
                    *error = "goal: " + name + " needs the rules of a game, and the setup has none (add \"game\" to it, "
                             "or --set game.rules=8-ball|9-ball|10-ball|snooker|three-cushion)";
                return std::nullopt;
            }
            if (t.kind == GoalTerm::Kind::Point && setup.game->rules != GameRules::ThreeCushion) {
                if (error) *error = "goal: point is a three-cushion term, and the setup's game is " + std::string(toString(setup.game->rules));
                return std::nullopt;
            }
            resolved.game_ = setup.game;
            resolved.terms_.push_back(term);
            continue;
        }
        if (t.kind != GoalTerm::Kind::StruckBallUp) {
            for (std::size_t i = 0; i < setup.balls.size(); ++i)
                if (setup.balls[i].id == t.ball) term.ball = static_cast<int>(i);
            if (term.ball < 0) {
                if (error) *error = "goal: there is no ball " + quoted(t.ball);
                return std::nullopt;
            }
        }
        if (t.kind == GoalTerm::Kind::Pocketed && !t.pocket.empty()) {
            std::string names;
            for (std::size_t i = 0; i < table.pockets.size(); ++i) {
                if (table.pockets[i].id == t.pocket) term.pocket = static_cast<int>(i);
                names += (names.empty() ? "" : ", ") + table.pockets[i].id;
            }
            if (term.pocket < 0) {
                if (error)
                    *error = "goal: there is no pocket " + quoted(t.pocket) +
                             (names.empty() ? " (this table has no pockets)" : " (expected one of: " + names + ")");
                return std::nullopt;
            }
        }
        resolved.terms_.push_back(term);
    }
    return resolved;
}

bool ResolvedGoal::met(const SimulationResult& result, const ShotOutcome& outcome) const
{
    std::optional<rules::Verdict> verdict;
    bool judged = false;
    const auto verdictOf = [&]() -> const std::optional<rules::Verdict>& {
        if (!judged && game_) verdict = rules::judgeShot(result, *game_);
        judged = true;
        return verdict;
    };
    for (const Term& t : terms_) {
        bool holds = false;
        switch (t.kind) {
        case GoalTerm::Kind::Pocketed:
            for (const PocketedBall& p : outcome.pocketed)
                holds = holds || (p.ball == t.ball && (t.pocket < 0 || p.pocket == t.pocket));
            break;
        case GoalTerm::Kind::FirstContact:
            holds = outcome.firstContact && outcome.firstContact->ball == t.ball;
            break;
        case GoalTerm::Kind::StruckBallUp: holds = !outcome.struckBallPocketed; break;
        case GoalTerm::Kind::EndsInRegion: {
            const auto index = static_cast<std::size_t>(t.ball);
            holds = index < outcome.finalStates.size() &&
                    outcome.finalStates[index].motion != MotionState::Pocketed &&
                    t.region.contains(outcome.finalStates[index].position);
            break;
        }
        case GoalTerm::Kind::CushionHits: {
            const auto index = static_cast<std::size_t>(t.ball);
            const int hits = index < outcome.cushionHits.size() ? outcome.cushionHits[index] : 0;
            holds = t.compare == GoalTerm::Compare::Equal    ? hits == t.count
                    : t.compare == GoalTerm::Compare::AtMost ? hits <= t.count
                                                             : hits >= t.count;
            break;
        }
        // A shot without a strike has no verdict: it is neither legal, nor scores, nor a point.
        case GoalTerm::Kind::Legal: holds = verdictOf() && verdictOf()->legal(); break;
        case GoalTerm::Kind::Scores: holds = verdictOf() && verdictOf()->legal() && verdictOf()->continues; break;
        case GoalTerm::Kind::Point: holds = verdictOf() && verdictOf()->points > 0; break;
        }
        if (holds == t.negated) return false;
    }
    return true;
}

}  // namespace cuelab::analysis
