#pragma once
// cuelab-bench --soak and --check (docs/soak.md): the random-shot soak of tests/soak, and its checks
// on setup files.

namespace cuelab::bench {

// --soak N SEED [--jobs J] [--out DIR] [--no-determinism] [--class NAME] [--max-events N] [--first K]
// (argv after "--soak"): shots K .. K + N - 1 of the soak SEED; prints the summary as JSON; exit 0, or
// 2 on a usage error.
int soakCommand(int argc, char** argv);

// --check [--set KEY=VALUE]... FILE... (argv after "--check"): loads each file, applies the
// overrides, simulates and checks the run; prints one line per file (and per failure); exit 1 if
// any file fails or does not load, 2 on a usage error.
int checkCommand(int argc, char** argv);

}  // namespace cuelab::bench
