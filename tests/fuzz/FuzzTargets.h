#pragma once
// The two coverage-guided fuzz targets (docs/fuzzing.md). Each takes the bytes of a would-be setup
// file; a broken invariant prints what broke and aborts, which libFuzzer reports as a crash with the
// input that caused it.
//   fuzzSetupLoader: bytes -> refused with a message naming the file, or loaded; a loaded setup is
//     saved, loaded again and saved again: the reload must give the same setup bit for bit and the
//     two saves the same bytes.
//   fuzzSimulator: a setup that loads -> simulate -> it ends (at rest, at its time limit, or at the
//     event cap with a message); no ball overlaps another ball or a cushion by more than 1e-9 m at any
//     event; no ball leaves the table except into a pocket; the kinetic energy never rises at an
//     event after the cue strike (beyond rounding and the documented separation allowance).

#include <cstddef>
#include <cstdint>

namespace cuelab::fuzz {

int fuzzSetupLoader(const std::uint8_t* data, std::size_t size);
int fuzzSimulator(const std::uint8_t* data, std::size_t size);

// Prints `what` to stderr and aborts when `ok` is false.
void check(bool ok, const char* what, double value = 0.0);

}  // namespace cuelab::fuzz
