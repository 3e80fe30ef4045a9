#pragma once
// Execution noise (PHYSICS.md, "Execution noise"): a player never strikes exactly the shot they mean.
// As in FastFiz, each strike parameter gets an independent normal error of its own standard deviation.
// The noise model, its presets, the key=sigma text form of `cuelab-cli odds --noise`, and the
// portable random numbers that draw the errors.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace cuelab::analysis {

// The strike keys that take noise, in the order their errors are drawn for every sample (a fixed
// order: adding noise to one key never changes the errors drawn for the others).
enum class StrikeKey { Heading, Speed, Side, Height, Elevation };
inline constexpr int kStrikeKeyCount = 5;
inline constexpr std::array<StrikeKey, kStrikeKeyCount> kStrikeKeys = {
    StrikeKey::Heading, StrikeKey::Speed, StrikeKey::Side, StrikeKey::Height, StrikeKey::Elevation};

// "shot.heading", "shot.speed", "shot.side", "shot.height", "shot.elevation".
std::string_view keyOf(StrikeKey key);
// The key's unit for people: "°", "m/s", "R".
std::string_view sigmaUnitOf(StrikeKey key);
std::optional<StrikeKey> strikeKeyOf(std::string_view key);

// Standard deviations of the normal errors; 0 = that parameter is struck exactly.
struct NoiseModel {
    std::array<double, kStrikeKeyCount> sigma{};  // indexed by StrikeKey: °, m/s, R, R, °

    double& operator[](StrikeKey key) { return sigma[static_cast<std::size_t>(key)]; }
    double operator[](StrikeKey key) const { return sigma[static_cast<std::size_t>(key)]; }
    bool any() const;
    bool operator==(const NoiseModel&) const = default;
};

// A named model: "fastfiz", "club", "pro" (docs/analysis.md says where each number comes from).
struct NoisePreset {
    std::string_view name;
    std::string_view description;  // for people: "FastFiz's defaults (computational pool tournaments)"
    double headingDeg, speed, tipOffset, elevationDeg;  // °, m/s, m (side and height alike), °
};
const std::vector<NoisePreset>& noisePresets();
// The preset named `name` with its tip offsets in radii of a ball of radius `ballRadius` (m);
// nullopt for an unknown name.
std::optional<NoiseModel> presetNoise(std::string_view name, double ballRadius);

// One `KEY=SIGMA` (or a preset name, which sets every key) applied to `model`; on error the message
// names the culprit: a key that is not a strike key, a sigma that is not a number or is negative.
std::optional<std::string> applyNoise(NoiseModel& model, std::string_view text, double ballRadius);

// "shot.heading=0.185,shot.speed=0.085" (keys with sigma > 0 only; round-trip numbers).
std::string noiseText(const NoiseModel& model);

// Random numbers that are the same on every platform and standard library: SplitMix64 (Steele,
// Lea and Flood 2014) for the bits and our own Box-Muller transform for the normals
// (std::normal_distribution's algorithm is not fixed by the standard and differs between libraries).
class SplitMix64 {
public:
    explicit SplitMix64(std::uint64_t state) : state_(state) {}
    std::uint64_t next();
    // Uniform in (0, 1], 53 random bits (never 0, so that log(u) is finite).
    double uniform();

private:
    std::uint64_t state_;
};

// The generator of sample `index` of a run with `seed`: a function of the two numbers alone, so that
// a sample's errors do not depend on which thread draws them or in which order.
SplitMix64 sampleGenerator(std::uint64_t seed, long long index);

// Standard normal errors (mean 0, deviation 1) of one sample, one per strike key in kStrikeKeys order.
std::array<double, kStrikeKeyCount> standardNormals(std::uint64_t seed, long long index);

}  // namespace cuelab::analysis
