#!/usr/bin/env bash
# How many instructions llvmpipe executes to render one frame: a measure of a shader change
# that does not move with the machine's load (wall-clock times on the 2-core development VM
# spread by 15-25 % between runs minutes apart; this count repeats to the instruction).
# `specula render ARGS` runs once under Valgrind's callgrind with one rasteriser thread
# (LP_NUM_THREADS=1); the script prints the instructions of each thread and their sum without
# thread 1, the application's own (loading, shader compilation, llvmpipe's vertex work), which
# leaves the rasteriser (fragment shading, depth, blending, resolves) and compute shaders. Warm
# the bake cache first (`specula bake MAP`): a bake is compute work and would be counted.
# Instructions are not time: arithmetic runs more of them per second than texture reads (pair
# B's four lights are 31 % of its instructions and 10-15 % of its time, the prefiltered read
# 13 % and 7-13 %), so confirm a change this count favours with interleaved timings
# (docs/performance.md).
#   scripts/frame-instructions.sh [SPECULA] RENDER_ARGS...
#   SPECULA_SHADER_DIR=/tmp/copy scripts/frame-instructions.sh build/specula learnopengl-ibl --camera 0
# One frame of pair B takes 2-3 minutes.
set -u
SPEC=build/specula
if [ $# -gt 0 ] && [ -x "$1" ] && [ ! -d "$1" ]; then SPEC=$1; shift; fi
[ $# -gt 0 ] || { echo "usage: scripts/frame-instructions.sh [SPECULA] SCENE [render options]" >&2; exit 2; }
[ -x "$SPEC" ] || { echo "frame-instructions.sh: no program at $SPEC (make build)" >&2; exit 1; }
command -v valgrind >/dev/null || { echo "frame-instructions.sh: needs valgrind (apt-get install valgrind)" >&2; exit 1; }
OUT=$(mktemp -d /tmp/frame-instructions.XXXXXX)
trap 'rm -rf "$OUT"' EXIT
if ! LP_NUM_THREADS=1 valgrind --tool=callgrind --separate-threads=yes --callgrind-out-file="$OUT/callgrind" \
    "$SPEC" render "$@" -o "$OUT/frame.png" >"$OUT/log" 2>&1; then
    echo "frame-instructions.sh: the render failed:" >&2
    grep -v '^==' "$OUT/log" | tail -5 >&2
    exit 1
fi
total=0
for f in "$OUT"/callgrind-*; do
    thread=${f##*-}
    count=$(awk '$1=="summary:"{print $2; exit}' "$f")
    printf 'thread %s  %15s instructions\n' "$thread" "$count"
    [ "$thread" = 01 ] || total=$((total + count))
done
printf 'rasteriser and compute (threads 2-)  %s instructions\n' "$total"
