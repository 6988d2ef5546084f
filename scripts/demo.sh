#!/usr/bin/env bash
# The main job, from a fresh machine: install what is missing, fetch the captures, build, then show what kumite
# reads from the reference kick capture, retarget it, bake the reference database, retrieve and adapt a strike,
# open the viewer on a bout when a display is present, and end on a 30 s headless bout's summary and its files.
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
echo
echo "== kumite bake: the reference annotations into build/demo/ref.kdb"
build/bin/kumite bake data/annotations/reference.json -o build/demo/ref.kdb
build/bin/kumite db-info build/demo/ref.kdb --verify
echo
echo "== kumite query and adapt: a left punch at a giant's head height"
build/bin/kumite query build/demo/ref.kdb --character giant --target 0.1,1.7,0.6 --command punch --side left
build/bin/kumite adapt build/demo/ref.kdb --character giant --target 0.1,1.7,0.6 --command punch --side left \
  --record build/demo/giant_punch.bvh --report build/demo/giant_punch.json
echo
display="${DISPLAY:-}${WAYLAND_DISPLAY:-}"
[[ -z "$display" ]] && echo "(no display, so no viewer after the bout: try xvfb-run -a scripts/demo.sh, or a desktop)" && echo
echo "== kumite play: a 30 s headless bout against a simulated user who punches back (its summary; the rest in the files)"
build/bin/kumite play build/demo/ref.kdb --character brawler --tracker simulate:punch --headless --duration 30 \
  --commands script:data/bouts/demo.txt --events build/demo/bout.jsonl --record build/demo/bout.bvh \
  --report build/demo/bout.json --html build/demo/bout.html
echo "  also         build/demo/: the retargeted kicks (kick_*.bvh), the adapted punch (giant_punch.bvh), the database (ref.kdb)"
if [[ -n "$display" ]]; then
  echo
  echo "== kumite play in the viewer (keys on screen: 1-6 strike, C character, V head-coupled camera, Esc quits)"
  build/bin/kumite play build/demo/ref.kdb --character brawler --tracker simulate:wander --commands script:data/bouts/demo.txt
fi
