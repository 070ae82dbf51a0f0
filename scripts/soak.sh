#!/usr/bin/env bash
# The long soak (make soak), two parts (docs/testing.md#soak records their figures):
#  1. 100,800 frames of tests/gl/test_soak.cpp, warm-up 3,600, with resident memory, the heap
#     in use and live GL objects printed at frame 3,600, every 10,800 and at the end
#     (SPECULA_SOAK_FRAMES overrides the count);
#  2. the viewer under Xvfb loading DamagedHelmet and an HDR (venice and studio in turn)
#     1,000 times by script (SPECULA_SOAK_LOADS overrides it), `log-memory` after load 10 and
#     every 100 loads: the GL objects must be the same as after load 10.
set -euo pipefail
BUILD="${1:-build}"
ASSETS="$(cd "$(dirname "$0")/.." && pwd)/../shared/assets"
# The camera turns every 100 frames (a circle in 3,600 frames); warm-up is one circle, the run
# 28 (100,800 frames), memory printed every 3 circles: always at the same point of the circle.
export SPECULA_SOAK_FRAMES="${SPECULA_SOAK_FRAMES:-100800}" SPECULA_SOAK_WARMUP="${SPECULA_SOAK_WARMUP:-3600}"
export SPECULA_SOAK_TURN="${SPECULA_SOAK_TURN:-100}" SPECULA_SOAK_REPORT="${SPECULA_SOAK_REPORT:-10800}"
LOADS="${SPECULA_SOAK_LOADS:-1000}"

if [ "${SPECULA_SOAK_SKIP_FRAMES:-0}" != 1 ]; then
  start=$(date +%s)
  "$BUILD/tests/specula_gl_tests" --gtest_filter='*Soak*'
  echo "soak: $SPECULA_SOAK_FRAMES frames in $(( $(date +%s) - start )) s"
fi

script=$(mktemp /tmp/specula-soak-XXXXXX.txt)
log=$(mktemp /tmp/specula-soak-XXXXXX.log)
trap 'rm -f "$script" "$log"' EXIT
for ((i = 1; i <= LOADS; ++i)); do
  env=venice_1k.hdr; [ $((i % 2)) = 0 ] && env=studio_1k.hdr
  printf 'open %s\nenv %s\nframes 1\n' "$ASSETS/models/DamagedHelmet/DamagedHelmet.glb" "$ASSETS/env/$env"
  if [ "$i" = 10 ] || [ $((i % 100)) = 0 ]; then printf 'log-memory\n'; fi
done > "$script"
printf 'expect-no-error\n' >> "$script"
start=$(date +%s)
if ! xvfb-run -a "$BUILD/specula" view --width 320 --height 240 --script "$script" > "$log" 2>&1; then
  tail -5 "$log" >&2
  echo "soak: the viewer failed" >&2
  exit 1
fi
grep 'memory:' "$log"
echo "soak: $LOADS viewer loads in $(( $(date +%s) - start )) s"
# Every GL object the viewer needs exists after load 10; one more by the end is a leak.
objects=$(grep -o 'GL objects [0-9]*' "$log" | awk '{print $3}' | sort -u | wc -l)
[ "$objects" = 1 ] || { echo "soak: the viewer's GL objects changed after load 10" >&2; exit 1; }
