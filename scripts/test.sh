#!/usr/bin/env bash
# Every test, from a fresh machine: install what is missing (incl. Blender for the BVH import check), fetch
# the captures, build in build/, run ctest.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/setup.sh" --test
"$root/scripts/fetch_mocap.sh"
"$root/scripts/build.sh"

# The BVH reader's fuzz target, when Clang and libFuzzer are there: every seed, then a minute of fuzzing.
if command -v clang++-14 >/dev/null && [[ "${KUMITE_SKIP_FUZZ:-}" != "1" ]]; then
  cmake -S "$root" -B "$root/build/fuzz" -DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DKUMITE_BUILD_TESTS=OFF -DKUMITE_BUILD_FUZZERS=ON >/dev/null
  cmake --build "$root/build/fuzz" --target bvh_reader_fuzz -j"$(nproc)"
  fuzzer="$root/build/fuzz/bin/bvh_reader_fuzz"
  corpus="$(mktemp -d)"
  trap 'rm -rf "$corpus"' EXIT
  "$fuzzer" -runs=0 -rss_limit_mb=2048 "$root/tests/fuzz/corpus" 2>&1 | tail -n 2
  "$fuzzer" -max_total_time="${KUMITE_FUZZ_SECONDS:-60}" -timeout=5 -rss_limit_mb=2048 -print_final_stats=1 \
    -dict="$root/tests/fuzz/bvh.dict" -artifact_prefix="$root/build/fuzz/" "$corpus" "$root/tests/fuzz/corpus" 2>&1 | tail -n 40
  echo "fuzz: no crash, leak, timeout or out-of-memory in ${KUMITE_FUZZ_SECONDS:-60} s"
fi

cd "$root/build"
ctest --output-on-failure -j"$(nproc)" --timeout 600
