#!/usr/bin/env bash
# Fills data/mocap (git-ignored) with the reference captures. Captures are never committed.
#   1. data/mocap already there: nothing to do.
#   2. ../shared/mocap beside the repository: a symbolic link to it.
#   3. otherwise: the public Bandai-Namco-Research-Motiondataset (CC BY-NC 4.0) from its GitHub repository,
#      unpacked into data/mocap/bandai-namco-1.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
target="$root/data/mocap"

if [[ -e "$target" ]]; then
  echo "fetch_mocap: $target present"
  exit 0
fi
if [[ -d "$root/../shared/mocap" ]]; then
  ln -s "$(cd "$root/../shared/mocap" && pwd)" "$target"
  echo "fetch_mocap: linked $target -> $(readlink "$target")"
  exit 0
fi

for tool in git unzip; do
  command -v "$tool" >/dev/null || { echo "fetch_mocap: needs $tool (apt-get install $tool)" >&2; exit 1; }
done
mkdir -p "$root/data"
work="$(mktemp -d "$root/data/.fetch.XXXXXX")" # same file system: the final mv is a rename
trap 'rm -rf "$work"' EXIT
echo "fetch_mocap: downloading the Bandai-Namco-Research-Motiondataset"
git clone --depth 1 https://github.com/BandaiNamcoResearchInc/Bandai-Namco-Research-Motiondataset.git "$work/repo"
mkdir -p "$work/mocap/bandai-namco-1" "$work/unpacked"
# The BVH files sit under dataset/Bandai-Namco-Research-Motiondataset-1/data, as files or zipped.
dataset="$(find "$work/repo" -type d -name 'Bandai-Namco-Research-Motiondataset-1' | head -n 1)"
[[ -n "$dataset" ]] || { echo "fetch_mocap: no Motiondataset-1 folder in the repository" >&2; exit 1; }
find "$dataset" -name '*.zip' -exec unzip -q -o {} -d "$work/unpacked" \;
find "$dataset" "$work/unpacked" -name '*.bvh' -exec mv -n {} "$work/mocap/bandai-namco-1/" \;
cp "$work/repo/LICENSE"* "$work/mocap/bandai-namco-1/" 2>/dev/null || true
mv "$work/mocap" "$target"
echo "fetch_mocap: $(find "$target" -name '*.bvh' | wc -l) captures in $target"
