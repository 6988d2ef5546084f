#!/usr/bin/env bash
# Every test, from a fresh machine: install what is missing (incl. Blender for the BVH import check), fetch
# the captures, build in build/, run ctest.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/setup.sh" --test
"$root/scripts/fetch_mocap.sh"
# Monado for the --xr tests: built once per archive into a cache outside the clone (~4 min on two cores; then
# instant), before the build so that a runtime that cannot be built fails the run here, not as skipped tests.
"$root/scripts/build_monado.sh" >/dev/null
# A compiler cache outside the clone, beside Monado's (KUMITE_CACHE_DIR, else /var/cache/kumite, else
# ~/.cache/kumite): a clean clone recompiles only the files that changed since a run on this machine (paths under
# the clone are hashed relative to it, so any clone folder hits). KUMITE_NO_CCACHE=1 compiles everything.
launcher=()
if command -v ccache >/dev/null && [[ "${KUMITE_NO_CCACHE:-}" != "1" ]]; then
  cache="${KUMITE_CACHE_DIR:-}"
  if [[ -z "$cache" ]]; then
    if mkdir -p /var/cache/kumite 2>/dev/null && [[ -w /var/cache/kumite ]]; then cache=/var/cache/kumite; else cache="$HOME/.cache/kumite"; fi
  fi
  export CCACHE_DIR="$cache/ccache" CCACHE_BASEDIR="$root" CCACHE_NOHASHDIR=1 CCACHE_MAXSIZE="${CCACHE_MAXSIZE:-4G}"
  launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  ccache --zero-stats >/dev/null
fi
# Optimised as the developer build (-O2, asserts off) but without debug info: a third less compile time on the
# heaviest files (a clean clone's run took 18.5 minutes on two cores). A crash under ctest is reproduced with
# scripts/build.sh.
"$root/scripts/build.sh" "${launcher[@]}" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O2 -DNDEBUG"

# The fuzz targets, when Clang and libFuzzer are there: every seed, then 30 s on the BVH reader, 15 s on the
# database opener, 10 s on the DTrack parser, 15 s on the glTF reader and 10 s on the drill reader (longer runs: the
# KUMITE_*_FUZZ_SECONDS variables, or tests/fuzz/README.md).
if command -v clang++-14 >/dev/null && [[ "${KUMITE_SKIP_FUZZ:-}" != "1" ]]; then
  # -O1 and line tables only (libFuzzer's own advice): a stack trace with lines, less to compile than -O2 -g.
  fuzz_generator=()
  if command -v ninja >/dev/null && [[ ! -f "$root/build/fuzz/CMakeCache.txt" ]]; then fuzz_generator=(-G Ninja); fi
  cmake -S "$root" -B "$root/build/fuzz" "${fuzz_generator[@]}" -DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_CXX_FLAGS_RELEASE="-O1 -gline-tables-only" "${launcher[@]}" -DKUMITE_BUILD_TESTS=OFF -DKUMITE_BUILD_FUZZERS=ON >/dev/null
  cmake --build "$root/build/fuzz" --target bvh_reader_fuzz database_fuzz dtrack_fuzz gltf_fuzz drill_fuzz -j"$(nproc)"
  work="$(mktemp -d)"
  trap 'rm -rf "$work"' EXIT
  run_fuzzer() { # NAME SEED_FOLDER SECONDS [EXTRA...]
    local fuzzer="$root/build/fuzz/bin/$1" seeds="$2" seconds="$3"
    shift 3
    mkdir -p "$work/$(basename "$fuzzer")"
    "$fuzzer" -runs=0 -rss_limit_mb=2048 "$seeds" 2>&1 | tail -n 2
    "$fuzzer" -max_total_time="$seconds" -timeout=5 -rss_limit_mb=2048 -print_final_stats=1 "$@" \
      -artifact_prefix="$root/build/fuzz/" "$work/$(basename "$fuzzer")" "$seeds" 2>&1 | tail -n 40
    echo "fuzz $(basename "$fuzzer"): no crash, leak, timeout or out-of-memory in $seconds s"
  }
  run_fuzzer bvh_reader_fuzz "$root/tests/fuzz/corpus" "${KUMITE_FUZZ_SECONDS:-30}" -dict="$root/tests/fuzz/bvh.dict"
  run_fuzzer database_fuzz "$root/tests/fuzz/database_corpus" "${KUMITE_DATABASE_FUZZ_SECONDS:-15}"
  run_fuzzer dtrack_fuzz "$root/tests/fuzz/dtrack_corpus" "${KUMITE_DTRACK_FUZZ_SECONDS:-10}"
  run_fuzzer gltf_fuzz "$root/tests/fuzz/gltf_corpus" "${KUMITE_GLTF_FUZZ_SECONDS:-15}"
  run_fuzzer drill_fuzz "$root/tests/fuzz/drill_corpus" "${KUMITE_DRILL_FUZZ_SECONDS:-10}"
fi

[[ ${#launcher[@]} -gt 0 ]] && ccache --show-stats 2>/dev/null | grep -iE "hits|misses" | head -n 3 || true
cd "$root/build"
ctest --output-on-failure -j"$(nproc)" --timeout 600
