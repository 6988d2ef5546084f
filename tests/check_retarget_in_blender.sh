#!/usr/bin/env bash
# Retargets a capture onto every shipped character and checks that Blender's BVH importer sees the joint
# positions kumite computes for each output. Exit 77 (skipped) without Blender.
# usage: check_retarget_in_blender.sh KUMITE CAPTURE CHARACTERS_DIR CHECK_SCRIPT
set -euo pipefail
kumite="$1" capture="$2" characters="$3" check="$4"
command -v blender >/dev/null || { echo "blender not installed: skipped"; exit 77; }
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
for file in "$characters"/*.bvh; do
  name="$(basename "$file" .bvh)"
  "$kumite" retarget "$capture" --character "$name" --characters-dir "$characters" -o "$out/$name.bvh" --report "$out/$name.json"
done
python3 "$check" --kumite "$kumite" --original --frames 30 --tolerance 1e-4 "$out"/*.bvh
