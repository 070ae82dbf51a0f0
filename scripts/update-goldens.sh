#!/usr/bin/env bash
# Rewrites the golden images (tests/golden/images) from the current build. Only on purpose:
# look at every changed image (git diff --stat, then the images themselves) before committing.
set -euo pipefail
BUILD="${1:-build}"
cmake --build "$BUILD"
SPECULA_UPDATE_GOLDENS=1 "$BUILD/tests/specula_golden_tests"
git status --short tests/golden/images
