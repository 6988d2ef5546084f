#!/usr/bin/env bash
# Bakes a large database for the retrieval benchmark.
#   scripts/make_large_database.sh [OUT.kdb]                 (default build/large.kdb)
#     the reference annotations plus every extension peak that `kumite suggest --segment` finds for both hands and
#     both feet in every Bandai capture (semantics `reach`, each mirrored): about 6,500 clips, 218,000 poses.
#   scripts/make_large_database.sh --not-strikes [OUT.kdb]   (default build/large_not_strikes.kdb)
#     the same from captures that hold no strike (walks, turns, waves, bows, dances: every Bandai content but
#     kick, punch and slash, and the CMU takes but 02_05 and 02_07-09), so most starts are near no target.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
kind=all
if [[ "${1:-}" == "--not-strikes" ]]; then kind=not_strikes; shift; fi
if [[ "$kind" == all ]]; then out="${1:-$root/build/large.kdb}"; else out="${1:-$root/build/large_not_strikes.kdb}"; fi
kumite="$root/build/bin/kumite"
mocap="${KUMITE_MOCAP_ROOT:-$root/data/mocap}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

captures=()
if [[ "$kind" == all ]]; then
  captures=("$mocap"/bandai-namco-1/*.bvh)
else
  for file in "$mocap"/bandai-namco-1/*.bvh "$mocap"/cmu-hahne-mb/*.bvh "$mocap"/cmu131-bvh11/*.bvh "$mocap"/mass-snu/*.bvh; do
    case "$(basename "$file")" in
      *_kick_*|*_punch_*|*_slash_*|02_05.bvh|02_07.bvh|02_08.bvh|02_09.bvh) ;;
      *) captures+=("$file") ;;
    esac
  done
fi
echo "${#captures[@]} captures" >&2

for segment in hand_l hand_r foot_l foot_r; do
  "$kumite" suggest "${captures[@]}" --segment "$segment" --mocap-root "$mocap" \
    --write-annotations "$work/$segment.json" >/dev/null
done
python3 - "$root/data/annotations/reference.json" "$work" "$work/large.json" "$kind" <<'PY'
import json, sys
reference, folder, out, kind = sys.argv[1:5]
merged = json.load(open(reference))
if kind == "not_strikes":
    merged["clips"] = [clip for clip in merged["clips"] if clip.get("semantics") not in ("kick", "punch", "slash")]
for segment in ("hand_l", "hand_r", "foot_l", "foot_r"):
    for clip in json.load(open(f"{folder}/{segment}.json"))["clips"]:
        clip["name"] = "reach_" + clip["name"]
        # Only the Bandai skeleton is symmetric enough to mirror (bake refuses the CMU ones' necks).
        clip["mirror"] = clip["mirror"] and clip["source"].startswith("bandai-namco-1/")
        merged["clips"].append(clip)
json.dump(merged, open(out, "w"))
print(f"{len(merged['clips'])} annotated clips")
PY
"$kumite" bake "$work/large.json" -o "$out" --mocap-root "$mocap" --clusters 64
