#!/usr/bin/env bash
# Bakes a large database for the retrieval benchmark: the reference annotations plus every extension peak that
# `kumite suggest --segment` finds for both hands and both feet in every Bandai capture (semantics `reach`, each
# mirrored). About 5,000 reach clips and 130,000 poses.
#   scripts/make_large_database.sh [OUT.kdb]      (default build/large.kdb)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="${1:-$root/build/large.kdb}"
kumite="$root/build/bin/kumite"
mocap="${KUMITE_MOCAP_ROOT:-$root/data/mocap}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
for segment in hand_l hand_r foot_l foot_r; do
  "$kumite" suggest "$mocap"/bandai-namco-1/*.bvh --segment "$segment" --mocap-root "$mocap" \
    --write-annotations "$work/$segment.json" >/dev/null
done
python3 - "$root/data/annotations/reference.json" "$work" "$work/large.json" <<'PY'
import json, sys
reference, folder, out = sys.argv[1], sys.argv[2], sys.argv[3]
merged = json.load(open(reference))
for segment in ("hand_l", "hand_r", "foot_l", "foot_r"):
    for clip in json.load(open(f"{folder}/{segment}.json"))["clips"]:
        clip["name"] = "reach_" + clip["name"]
        merged["clips"].append(clip)
json.dump(merged, open(out, "w"))
print(f"{len(merged['clips'])} annotated clips")
PY
"$kumite" bake "$work/large.json" -o "$out" --mocap-root "$mocap" --clusters 64
