#!/usr/bin/env bash
# Coverage-guided fuzzing of the setup loader and the simulator with clang's libFuzzer
# (docs/fuzzing.md). Builds build-fuzz/ with clang, AddressSanitizer, UndefinedBehaviorSanitizer and
# libFuzzer's coverage, then runs each target on a working corpus seeded from resources/examples.
#   scripts/fuzz.sh --ci            a short, reproducible run of both targets (fixed seed and runs; CI)
#   scripts/fuzz.sh [SECONDS]       a long run of each target (default 3600 s each), on all cores
# A crash leaves its input in build-fuzz/artifacts/; copy it into tests/fuzz/corpus/ once fixed, so that
# tst_fuzzreplay keeps checking it in every build. A long run's worker logs (fuzz-N.log) go to
# build-fuzz/logs/TARGET/.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${CUELAB_FUZZ_BUILD_DIR:-$root/build-fuzz}
mode=long
seconds=3600
case "${1:-}" in
  --ci) mode=ci ;;
  "") ;;
  *) seconds=$1 ;;
esac

flags="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
  -DCUELAB_CORE_ONLY=ON -DCUELAB_FUZZ=ON -DCMAKE_CXX_FLAGS="$flags" "${launcher[@]}" >/dev/null
cmake --build "$build" --target fuzz_setup fuzz_simulate

export ASAN_OPTIONS=detect_leaks=0:abort_on_error=1:allocator_may_return_null=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
mkdir -p "$build/artifacts"
for target in fuzz_setup fuzz_simulate; do
  corpus="$build/corpus/$target"
  mkdir -p "$corpus"
  # The seeds: every bundled example and every input that once broke a target.
  cp -n "$root"/resources/examples/*.json "$corpus"/ 2>/dev/null || true
  cp -n "$root"/tests/fuzz/corpus/* "$corpus"/ 2>/dev/null || true
  common=(-max_len=8192 -timeout=10 -rss_limit_mb=2048 -artifact_prefix="$build/artifacts/$target-"
          -dict="$root/tests/fuzz/setup.dict" -print_final_stats=1)
  echo "== $target ($mode)"
  if [ "$mode" = ci ]; then
    # Reproducible: one process, a fixed seed, a fixed number of runs (about 30 s on one core).
    runs=$([ "$target" = fuzz_setup ] && echo 60000 || echo 6000)
    "$build/$target" "${common[@]}" -seed=13 -runs="$runs" "$corpus" 2>&1 | tail -n 25
  else
    jobs=$(nproc)
    # With -jobs libFuzzer writes each worker's fuzz-N.log into the current folder: run it in the fuzz
    # build's own folder for the target, never in the repository.
    logs="$build/logs/$target"
    mkdir -p "$logs"
    (cd "$logs" && "$build/$target" "${common[@]}" -max_total_time="$seconds" -jobs="$jobs" -workers="$jobs" "$corpus" \
      2>&1 | tail -n 40)
  fi
done
