#!/usr/bin/env bash
# Builds Monado (the OpenXR runtime the --xr tests run against) from ../shared/vendor into a cache outside the clone,
# keyed on the archive's sha256: built once per archive, reused by every clone and run. Prints the build folder
# (which holds openxr_monado-dev.json, the runtime manifest) on stdout; progress goes to stderr.
#   scripts/build_monado.sh [ARCHIVE]     (default ../shared/vendor/monado-*.tar.gz beside the clone)
# Cache root: $KUMITE_CACHE_DIR, else /var/cache/kumite when writable, else ~/.cache/kumite.
# Only the in-process runtime target (openxr_monado) with the remote and simulated drivers: ~2.5 min on two cores.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
archive="${1:-}"
if [[ -z "$archive" ]]; then
  archive="$(ls "$root"/../shared/vendor/monado-*.tar.gz 2>/dev/null | head -n 1 || true)"
fi
[[ -n "$archive" && -f "$archive" ]] || { echo "build_monado: no Monado archive (looked for ../shared/vendor/monado-*.tar.gz)" >&2; exit 1; }

cache="${KUMITE_CACHE_DIR:-}"
if [[ -z "$cache" ]]; then
  if mkdir -p /var/cache/kumite 2>/dev/null && [[ -w /var/cache/kumite ]]; then cache=/var/cache/kumite; else cache="$HOME/.cache/kumite"; fi
fi
hash="$(sha256sum "$archive" | cut -c1-16)"
dir="$cache/monado-$hash"
manifest="$dir/build/openxr_monado-dev.json"
if [[ -f "$dir/.complete" && -f "$manifest" ]]; then
  echo "build_monado: cached in $dir" >&2
  echo "$dir/build"
  exit 0
fi

echo "build_monado: building $(basename "$archive") into $dir" >&2
rm -rf "$dir"
mkdir -p "$dir/source"
tar -xzf "$archive" -C "$dir/source" --strip-components=1
drivers=()
for driver in $(grep -oh 'XRT_BUILD_DRIVER_[A-Z0-9_]*' "$dir/source/CMakeLists.txt" | sort -u); do
  case "$driver" in
    XRT_BUILD_DRIVER_REMOTE|XRT_BUILD_DRIVER_SIMULATED) drivers+=("-D$driver=ON") ;;
    *) drivers+=("-D$driver=OFF") ;;
  esac
done
generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
start=$SECONDS
cmake -S "$dir/source" -B "$dir/build" "${generator[@]}" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DXRT_FEATURE_SERVICE=OFF -DXRT_MODULE_IPC=OFF -DBUILD_TESTING=OFF -DXRT_BUILD_SAMPLES=OFF \
  -DXRT_MODULE_MONADO_CLI=OFF -DXRT_MODULE_MONADO_GUI=OFF -DXRT_FEATURE_STEAMVR_PLUGIN=OFF -DXRT_HAVE_SDL2=OFF \
  -DXRT_HAVE_OPENCV=OFF -DXRT_FEATURE_DEBUG_GUI=OFF -DXRT_FEATURE_WINDOW_PEEK=OFF "${drivers[@]}" >"$dir/configure.log" 2>&1 \
  || { tail -n 40 "$dir/configure.log" >&2; echo "build_monado: configure failed (log: $dir/configure.log)" >&2; exit 1; }
nice -n 5 cmake --build "$dir/build" --target openxr_monado -j"$(nproc)" >"$dir/build.log" 2>&1 \
  || { tail -n 40 "$dir/build.log" >&2; echo "build_monado: build failed (log: $dir/build.log)" >&2; exit 1; }
[[ -f "$manifest" ]] || { echo "build_monado: built, but no $manifest" >&2; exit 1; }
rm -rf "$dir/source/.git"
touch "$dir/.complete"
echo "build_monado: built in $((SECONDS - start)) s" >&2
echo "$dir/build"
