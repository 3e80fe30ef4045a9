#include "Noise.h"

#include "Override.h"
#include "Refusal.h"

#include <cmath>
#include <numbers>

namespace cuelab::analysis {

std::string_view keyOf(StrikeKey key)
{
    switch (key) {
    case StrikeKey::Heading: return "shot.heading";
    case StrikeKey::Speed: return "shot.speed";
    case StrikeKey::Side: return "shot.side";
    case StrikeKey::Height: return "shot.height";
    case StrikeKey::Elevation: return "shot.elevation";
    }
    return "";
}

std::string_view sigmaUnitOf(StrikeKey key)
{
    switch (key) {
    case StrikeKey::Heading:
    case StrikeKey::Elevation: return "°";
    case StrikeKey::Speed: return "m/s";
    case StrikeKey::Side:
    case StrikeKey::Height: return "R";
    }
    return "";
}

std::optional<StrikeKey> strikeKeyOf(std::string_view key)
{
    for (StrikeKey k : kStrikeKeys)
        if (keyOf(k) == key) return k;
    return std::nullopt;
}

bool NoiseModel::any() const
{
    for (double s : sigma)
        if (s > 0.0) return true;
    return false;
}

const std::vector<NoisePreset>& noisePresets()
{
    // FastFiz (Leckie and Greenspan's pool physics library, the engine of the ICGA computational
    // pool tournaments): its default noise, PHYSICS.md "Execution noise". The club player and the
    // professional are CueLab's own choices, scaled from it; docs/analysis.md gives the reasons and
    // what each makes of the example shots.
    static const std::vector<NoisePreset> presets = {
        {"fastfiz", "FastFiz's default noise (computational pool tournaments)", 0.185, 0.085, 0.0005, 0.03},
        {"club", "a club player", 0.3, 0.12, 0.0015, 0.3},
        {"pro", "a professional", 0.1, 0.05, 0.0005, 0.1},
    };
    return presets;
}

std::optional<NoiseModel> presetNoise(std::string_view name, double ballRadius)
{
    for (const NoisePreset& p : noisePresets()) {
        if (p.name != name) continue;
        NoiseModel m;
        m[StrikeKey::Heading] = p.headingDeg;
        m[StrikeKey::Speed] = p.speed;
        m[StrikeKey::Side] = p.tipOffset / ballRadius;  // the setup's tip offsets are in radii
        m[StrikeKey::Height] = p.tipOffset / ballRadius;
        m[StrikeKey::Elevation] = p.elevationDeg;
        return m;
    }
    return std::nullopt;
}

std::optional<std::string> applyNoise(NoiseModel& model, std::string_view text, double ballRadius)
{
    const auto assignment = parseAssignment(text);
    if (!assignment) {
        if (auto preset = presetNoise(text, ballRadius)) {
            model = *preset;
            return std::nullopt;
        }
        std::string names;
        for (const NoisePreset& p : noisePresets()) names += (names.empty() ? "" : ", ") + std::string(p.name);
        return "expected KEY=SIGMA or a preset (" + names + "), found \"" + std::string(text) + "\"";
    }
    const auto key = strikeKeyOf(assignment->key);
    if (!key) {
        std::string keys;
        for (StrikeKey k : kStrikeKeys) keys += (keys.empty() ? "" : ", ") + std::string(keyOf(k));
        return "\"" + assignment->key + "\" is not a strike key (noise applies to " + keys + ")";
    }
    const auto sigma = parseNumber(assignment->value);
    if (!sigma) return assignment->key + ": SIGMA is not a number: \"" + assignment->value + "\"";
    if (*sigma < 0.0) return assignment->key + ": SIGMA must not be negative, found " + assignment->value;
    model[*key] = *sigma;
    return std::nullopt;
}

std::string noiseText(const NoiseModel& model)
{
    std::string out;
    for (StrikeKey k : kStrikeKeys) {
        if (model[k] <= 0.0) continue;
        out += (out.empty() ? "" : ",") + std::string(keyOf(k)) + "=" + roundTrip(model[k]);
    }
    return out;
}

std::uint64_t SplitMix64::next()
{
    // Steele, Lea and Flood, "Fast splittable pseudorandom number generators" (OOPSLA 2014); the
    // constants of Vigna's reference implementation (prng.di.unimi.it/splitmix64.c).
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

double SplitMix64::uniform()
{
    // The top 53 bits give k in [0, 2^53); (k + 1) / 2^53 lies in (0, 1], exactly representable.
    return static_cast<double>((next() >> 11) + 1) * 0x1.0p-53;
}

SplitMix64 sampleGenerator(std::uint64_t seed, long long index)
{
    // Two rounds of SplitMix64's output function decorrelate neighbouring seeds and indices: the
    // state is a hash of (seed, index), not seed + index (which would make sample i of seed s equal
    // sample i - 1 of seed s + 1).
    SplitMix64 seeded(seed);
    const std::uint64_t a = seeded.next();
    SplitMix64 indexed(a ^ static_cast<std::uint64_t>(index));
    return SplitMix64(indexed.next());
}

std::array<double, kStrikeKeyCount> standardNormals(std::uint64_t seed, long long index)
{
    // Box-Muller (1958): for u1, u2 uniform on (0, 1], sqrt(-2 ln u1) (cos, sin)(2 pi u2) are two
    // independent standard normals. Three pairs give the five errors (the sixth is not used).
    SplitMix64 rng = sampleGenerator(seed, index);
    std::array<double, kStrikeKeyCount> z{};
    for (std::size_t i = 0; i < z.size(); i += 2) {
        const double u1 = rng.uniform(), u2 = rng.uniform();
        const double r = std::sqrt(-2.0 * std::log(u1));
        const double angle = 2.0 * std::numbers::pi * u2;
        z[i] = r * std::cos(angle);
        if (i + 1 < z.size()) z[i + 1] = r * std::sin(angle);
    }
    return z;
}

}  // namespace cuelab::analysis
