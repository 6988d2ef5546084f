#!/usr/bin/env bash
# The main job, from a fresh machine: install what is missing, fetch the captures, build, and show what
# kumite reads from the reference kick capture.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/setup.sh"
"$root/scripts/fetch_mocap.sh"
"$root/scripts/build.sh"
capture="bandai-namco-1/dataset-1_kick_normal_001.bvh"
cd "$root"
echo
echo "== kumite inspect $capture"
build/bin/kumite inspect "$capture"
echo
echo "== kumite positions $capture --frames 60 (the apex of the first right kick)"
build/bin/kumite positions "$capture" --frames 60 | head -n 12
echo
echo "== kumite retarget $capture onto every character (output in build/demo/)"
mkdir -p build/demo
build/bin/kumite characters
for character in kid scout brawler runner giant; do
  build/bin/kumite retarget "$capture" --character "$character" -o "build/demo/kick_$character.bvh" \
    --report "build/demo/kick_$character.json"
done
