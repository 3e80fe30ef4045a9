#pragma once
// Random legal shots for the soak and the property suite (docs/soak.md, "The classes"): a shot is a
// pure function of (seed, index), so a failure is found again from its two numbers on any machine
// and with any number of threads. Every setup passes core/setup's validator. Standard library and
// Eigen only, no Qt.

#include "Setup.h"

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace cuelab::soak {

enum class ShotClass : std::uint8_t {
    Property,  // tst_properties' draws: 2-15 balls at random, frozen together, on rails, facings and
               // jaws, squeezed into junctions; some already moving; struck, unstruck or grazing
    Cluster,   // a frozen cluster of up to 40 touching balls (random or packed), struck into or within
    Rail,      // balls frozen against rails and jaws (and to each other along a rail), struck into
               // them, or spinning into a rail
    Break,     // an 8-ball or 9-ball rack (core/physics/Racks.h) broken from a random cue position,
               // heading, tip offset and speed
    Elevated,  // elevated and massé strikes (elevation 15-89 degrees, tip far from the centre)
    Moving,    // balls already moving and spinning, no strike
};

std::string_view toString(ShotClass c);  // "property", "cluster", "rail", "break", "elevated", "moving"
std::optional<ShotClass> parseShotClass(std::string_view text);
std::span<const ShotClass> shotClasses();  // every class, in the order above

// Where the property generator put a ball (counted so that a suite can insist that it reaches them).
enum class Placement : std::uint8_t { Random, Frozen, Cushion, Jaw, Squeezed };
inline constexpr std::size_t kPlacements = 5;

struct RandomShot {
    Setup setup;  // legal (validateSetup finds nothing)
    ShotClass shotClass = ShotClass::Property;
    std::uint64_t seed = 0;
    std::uint64_t index = 0;
    std::array<int, kPlacements> placed{};  // balls placed by each Placement (Property, Rail, Moving)
    bool moving = false;                    // a ball moves before any strike
    std::string grazed;                     // a grazing shot: the id of the ball it aims past ("" if none)
    bool wide = false;                      // drawn by wideRandomShot
};

// The shot `index` of the soak `seed`; its class drawn from the pair (Property 30 %, Cluster 15 %,
// Rail 15 %, Break 15 %, Elevated 10 %, Moving 15 %).
RandomShot randomShot(std::uint64_t seed, std::uint64_t index);
// The shot `index` of the soak `seed` within one class (a different stream from the mixed one).
RandomShot randomShot(std::uint64_t seed, std::uint64_t index, ShotClass shotClass);
// ... on one table (the property suite runs a row per table).
RandomShot randomShot(std::uint64_t seed, std::uint64_t index, ShotClass shotClass, TableKind table);

// The widened soak (issue 40, `cuelab-bench --soak ... --wide`): the same classes and shares, with the
// physics drawn over the whole legal range (randomPhysicsWide: cloth, restitutions down to 0.5 and
// 0.4 and up to 1, elastic balls, soft and lively cushions, both ball-ball laws, every cushion model)
// and racks struck from anywhere on the table. Its own streams: randomShot's shots stay the same for
// every seed.
RandomShot wideRandomShot(std::uint64_t seed, std::uint64_t index);
RandomShot wideRandomShot(std::uint64_t seed, std::uint64_t index, ShotClass shotClass);

}  // namespace cuelab::soak
