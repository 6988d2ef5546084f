#!/usr/bin/env bash
# Configures and builds kumite in build/ (executables in build/bin/). Extra arguments go to cmake.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
werror=OFF
[[ "${CI:-}" == "true" ]] && werror=ON
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DKUMITE_WERROR="$werror" "$@" >/dev/null
cmake --build "$root/build" -j"$(nproc)"
