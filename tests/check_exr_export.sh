#!/usr/bin/env bash
# `kumite bake --exr` writes EXR files that OpenEXR's own exrheader opens: the pose-distance matrix (one FLOAT
# channel, poses x poses) and one RGBA FLOAT animation texture per clip. Exit 77 (skipped) without exrheader.
#   check_exr_export.sh KUMITE ANNOTATIONS MOCAP_ROOT
set -euo pipefail
kumite=$1 annotations=$2 mocap_root=$3
command -v exrheader >/dev/null || { echo "exrheader not installed (Debian package openexr): skipped"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$kumite" bake "$annotations" -o "$work/db.kdb" --mocap-root "$mocap_root" --clusters 4 --exr "$work/exr" >/dev/null
poses=$("$kumite" db-info "$work/db.kdb" --json | python3 -c 'import json,sys; print(json.load(sys.stdin)["poses"])')
clips=$("$kumite" db-info "$work/db.kdb" --json | python3 -c 'import json,sys; print(json.load(sys.stdin)["clips"])')
header=$(exrheader "$work/exr/pose_distance.exr")
grep -q "Y, 32-bit floating-point" <<<"$header" || { echo "pose_distance.exr: no FLOAT Y channel"; exit 1; }
last=$((poses - 1))
grep -q "dataWindow (type box2i): (0 0) - ($last $last)" <<<"$header" || { echo "pose_distance.exr: not $poses x $poses"; echo "$header"; exit 1; }
textures=$(ls "$work/exr"/clip_*.exr | wc -l)
[[ $textures -eq $clips ]] || { echo "$textures animation textures for $clips clips"; exit 1; }
for file in "$work/exr"/clip_*.exr; do
  header=$(exrheader "$file")
  for channel in R G B A; do
    grep -q "$channel, 32-bit floating-point" <<<"$header" || { echo "$file: no FLOAT $channel channel"; exit 1; }
  done
  grep -q "kumite:joints (type stringvector)" <<<"$header" || { echo "$file: no joint names"; exit 1; }
done
ls "$work/exr" | grep -q partial && { echo "a temporary file was left behind"; exit 1; }
echo "pose_distance.exr ${poses}x${poses} and $textures animation textures open in exrheader"
