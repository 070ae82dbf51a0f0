#!/usr/bin/env bash
# Pair B of the LearnOpenGL side by side without a bake cache: the tutorial's specular IBL
# program (which bakes at every launch) and `specula view learnopengl-ibl --no-cache`, the same
# 1280x720 window under Xvfb, interleaved over ROUNDS rounds, timed by the side-by-side's own
# harness (run_one.sh and its swap timer). Prints each run's first frame after launch and the
# ratio tutorial / Specula. ../shared/peers/learnopengl/side-by-side.sh measures warm caches only.
#   scripts/cold-start.sh [SPECULA] [ROUNDS]
# Environment: OUT (results folder, default a new temporary one), PEER_SECONDS (window after the
# first frame, default 5), QUIET=0 to skip waiting for an idle machine before each run.
set -u
SPEC=$(readlink -f "${1:-build/specula}")
ROUNDS=${2:-3}
PEERS="$(cd "$(dirname "$0")/../.." && pwd)/shared/peers/learnopengl"
[ -x "$PEERS/2.2.1.ibl_specular/program" ] || { echo "cold-start.sh: no tutorial program under $PEERS" >&2; exit 1; }
command -v Xvfb >/dev/null || { echo "cold-start.sh: needs Xvfb (apt-get install xvfb)" >&2; exit 1; }
OUT=${OUT:-$(mktemp -d /tmp/cold-start.XXXXXX)}
mkdir -p "$OUT"
export PEER_SECONDS=${PEER_SECONDS:-5} LOGL_ROOT_PATH=$PEERS
gcc -O2 -shared -fPIC -o "$OUT/swapshim.so" "$PEERS/harness/swapshim.c" -ldl -lm || exit 1
export SHIM="$OUT/swapshim.so"
for d in $(seq 81 89); do [ -e "/tmp/.X11-unix/X$d" ] || break; done
Xvfb ":$d" -screen 0 1920x1080x24 -nolisten tcp >"$OUT/xvfb.log" 2>&1 &
export XVFB_PID=$!
trap 'kill $XVFB_PID 2>/dev/null' EXIT
export DISPLAY=:$d
sleep 1
HDR=$PEERS/resources/textures/hdr/newport_loft.hdr
quiet() { [ "${QUIET:-1}" = 0 ] || "$PEERS/harness/wait_quiet.sh" 0.05 3 600 >/dev/null; }
first() { awk -F= '$1=="startup_first_frame_s"{print $2}' "$1"; }
for round in $(seq "$ROUNDS"); do
  quiet
  "$PEERS/harness/run_one.sh" "$OUT/tutorial.run$round" "$PEERS/2.2.1.ibl_specular" "$PEERS/2.2.1.ibl_specular/program"
  quiet
  "$PEERS/harness/run_one.sh" "$OUT/specula.run$round" "$PWD" "$SPEC" view learnopengl-ibl --camera 0 --env "$HDR" \
    --hide-ui --width 1280 --height 720 --no-cache
  t=$(first "$OUT/tutorial.run$round"); s=$(first "$OUT/specula.run$round")
  awk -v r="$round" -v t="$t" -v s="$s" \
    'BEGIN{printf "round %s: first frame, tutorial %.2f s, Specula --no-cache %.2f s -> %.1fx earlier\n", r, t, s, t/s}'
done | tee "$OUT/cold-start.txt"
echo "results: $OUT"
