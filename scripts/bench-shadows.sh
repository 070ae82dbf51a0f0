#!/usr/bin/env bash
# The shadows' cost (docs/performance.md): each scene with shadows off, cached (the default: a
# still camera draws no map after the first frame) and drawn every frame (--shadows-cache off),
# at 1280x720, ROUNDS interleaved rounds. Prints one markdown row per scene, mode and round:
# the frame's median, the forward pass's, and each shadow pass's own GPU time.
# Usage: scripts/bench-shadows.sh [build] (ROUNDS=2 FRAMES=10 by default)
set -euo pipefail
BUILD="${1:-build}"
SHARED="$(cd "$(dirname "$0")/../../shared/assets" && pwd)"
ROUNDS="${ROUNDS:-2}"
FRAMES="${FRAMES:-10}"
# BreakfastRoom has no lights of its own: without an environment it gets the default rig (a
# sun, a fill and a rim light, all casting), whose sun falls through the window's blinds.
if [ -n "${ONLY:-}" ]; then read -ra SCENES <<<"$ONLY"; else SCENES=(demo learnopengl "$SHARED/models/BreakfastRoom/BreakfastRoom.gltf"); fi
declare -A EXTRA=(["$SHARED/models/BreakfastRoom/BreakfastRoom.gltf"]="--env none")
JSON=$(mktemp)
trap 'rm -f "$JSON"' EXIT
echo "| scene | shadows | frame ms | forward ms | shadow passes ms | round |"
echo "|---|---|---|---|---|---|"
for round in $(seq 1 "$ROUNDS"); do
  for scene in "${SCENES[@]}"; do
    for mode in off cached every; do
      case $mode in
        off) flags=(--shadows off) ;;
        cached) flags=() ;;
        every) flags=(--shadows-cache off) ;;
      esac
      # shellcheck disable=SC2086
      "$BUILD/specula" bench --scene "$scene" --frames "$FRAMES" --warmup 2 ${EXTRA[$scene]:-} "${flags[@]}" -o "$JSON" >/dev/null 2>&1
      python3 - "$JSON" "$mode" "$round" <<'PY'
import json, os, sys
r = json.load(open(sys.argv[1]))["results"][0]
passes = r["passesGpuMs"]
shadow = {k: v["median"] for k, v in passes.items() if k.startswith("shadows")}
listed = ", ".join(f"{k.split(': ')[1]} {v:.1f}" for k, v in shadow.items()) or "none drawn"
name = os.path.basename(r["scene"]).split(".")[0]
print(f"| {name} | {sys.argv[2]} | {r['frameGpuMs']['median']:.1f} | {passes['forward']['median']:.1f} | {listed} | {sys.argv[3]} |")
PY
    done
  done
done
