#!/usr/bin/env bash
# Re-bakes the golden database, data/golden/golden-v<FORMAT>.kdb, from data/annotations/golden.json.
# Run it after a deliberate change to what the bake produces (and bump the format version in
# formats/include/kumite/formats/database_image.h when the layout changed). The bake test fails until you do.
set -euo pipefail
cd "$(dirname "$0")/.."
version=$(sed -n 's/.*k_database_format_version = \([0-9]*\);/\1/p' formats/include/kumite/formats/database_image.h)
build/bin/kumite bake data/annotations/golden.json -o "data/golden/golden-v${version}.kdb" --mocap-root data/mocap --clusters 4 --jobs 2
build/bin/kumite db-info "data/golden/golden-v${version}.kdb" --verify
