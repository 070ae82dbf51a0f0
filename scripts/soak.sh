#!/usr/bin/env bash
# The long soak (make soak): 100,000 frames of tests/gl/test_soak.cpp, warm-up 1,000, with
# resident memory and live GL objects printed at frame 1,000, every 10,000 and at the end
# (docs/testing.md#soak records them). SPECULA_SOAK_FRAMES overrides the count.
set -euo pipefail
BUILD="${1:-build}"
export SPECULA_SOAK_FRAMES="${SPECULA_SOAK_FRAMES:-100000}" SPECULA_SOAK_WARMUP="${SPECULA_SOAK_WARMUP:-1000}"
start=$(date +%s)
"$BUILD/tests/specula_gl_tests" --gtest_filter='*Soak*'
echo "soak: $SPECULA_SOAK_FRAMES frames in $(( $(date +%s) - start )) s"
