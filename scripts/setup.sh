#!/usr/bin/env bash
# Installs the Debian packages kumite needs, only those missing. Safe to run again.
#   scripts/setup.sh          build dependencies
#   scripts/setup.sh --test   also what the tests use (Blender for the BVH import check, clang for fuzzing,
#                             Xvfb and Mesa for the viewer checks, what Monado needs to build for the --xr tests)
set -euo pipefail

packages=(build-essential cmake ninja-build g++ libeigen3-dev nlohmann-json3-dev libtinygltf-dev catch2 python3 libopenexr-dev libflann-dev
          qt6-base-dev qt6-qpa-plugins libqt6opengl6-dev libgl-dev libxkbcommon-dev fonts-dejavu-core
          pybind11-dev python3-dev python3-numpy libopenxr-dev libopenxr-loader1 libx11-dev libtoml11-dev libsqlite3-dev)
if [[ "${1:-}" == "--test" ]]; then
  packages+=(blender python3-pytest python3-matplotlib python3-pandas clang-14 libfuzzer-14-dev openexr xvfb xauth libgl1-mesa-dri ccache
            # Monado, the OpenXR runtime the --xr tests run against (scripts/build_monado.sh), and Vulkan on the CPU
            # (lavapipe: Monado allocates the swapchains with Vulkan even for an OpenGL client)
            ninja-build pkg-config libudev-dev glslang-tools libvulkan-dev libegl-dev libx11-xcb-dev libxcb-randr0-dev
            libxrandr-dev mesa-vulkan-drivers)
fi

missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
done
if [[ ${#missing[@]} -eq 0 ]]; then
  echo "setup: all packages present"
  exit 0
fi

sudo_prefix=()
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || { echo "setup: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  sudo_prefix=(sudo)
fi
echo "setup: installing ${missing[*]}"
"${sudo_prefix[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo_prefix[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
