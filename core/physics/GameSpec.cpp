#include "GameSpec.h"

#include <array>
#include <utility>

namespace cuelab {

namespace {

template <typename E, std::size_t N>
using NameTable = std::array<std::pair<E, std::string_view>, N>;

constexpr NameTable<GameRules, 5> kRules{{{GameRules::EightBall, "8-ball"},
                                          {GameRules::NineBall, "9-ball"},
                                          {GameRules::TenBall, "10-ball"},
                                          {GameRules::Snooker, "snooker"},
                                          {GameRules::ThreeCushion, "three-cushion"}}};
constexpr NameTable<PoolGroup, 3> kGroups{
    {{PoolGroup::Open, "open"}, {PoolGroup::Solids, "solids"}, {PoolGroup::Stripes, "stripes"}}};
constexpr NameTable<SnookerOn, 8> kOn{{{SnookerOn::Red, "red"},
                                       {SnookerOn::Colour, "colour"},
                                       {SnookerOn::Yellow, "yellow"},
                                       {SnookerOn::Green, "green"},
                                       {SnookerOn::Brown, "brown"},
                                       {SnookerOn::Blue, "blue"},
                                       {SnookerOn::Pink, "pink"},
                                       {SnookerOn::Black, "black"}}};

template <typename E, std::size_t N>
std::string_view nameOf(const NameTable<E, N>& table, E value)
{
    for (const auto& [e, name] : table)
        if (e == value) return name;
    return {};
}

template <typename E, std::size_t N>
bool valueOf(const NameTable<E, N>& table, std::string_view text, E& out)
{
    for (const auto& [e, name] : table)
        if (name == text) {
            out = e;
            return true;
        }
    return false;
}

// "a, b or c"
template <typename E, std::size_t N>
std::string namesOf(const NameTable<E, N>& table)
{
    std::string out;
    for (std::size_t i = 0; i < N; ++i) {
        if (i > 0) out += i + 1 == N ? " or " : ", ";
        out += table[i].second;
    }
    return out;
}

}  // namespace

std::string_view toString(GameRules rules) { return nameOf(kRules, rules); }
std::string_view toString(PoolGroup group) { return nameOf(kGroups, group); }
std::string_view toString(SnookerOn on) { return nameOf(kOn, on); }
bool parseGameRules(std::string_view text, GameRules& out) { return valueOf(kRules, text, out); }
bool parsePoolGroup(std::string_view text, PoolGroup& out) { return valueOf(kGroups, text, out); }
bool parseSnookerOn(std::string_view text, SnookerOn& out) { return valueOf(kOn, text, out); }
std::string gameRulesNames() { return namesOf(kRules); }
std::string poolGroupNames() { return namesOf(kGroups); }
std::string snookerOnNames() { return namesOf(kOn); }

}  // namespace cuelab
