#!/usr/bin/env bash
# Every test, from a fresh machine: install what is missing (incl. Blender for the BVH import check), fetch
# the captures, build in build/, run ctest.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/setup.sh" --test
"$root/scripts/fetch_mocap.sh"
"$root/scripts/build.sh"
cd "$root/build"
ctest --output-on-failure -j"$(nproc)" --timeout 600
