#!/usr/bin/env bash
# Renders a fixed set of frames with two builds of specula and compares the files byte for
# byte: for refactors that must not change a pixel (the frame graph's, for one).
#   scripts/compare-renders.sh OLD_SPECULA OLD_SHADER_DIR [NEW_SPECULA]
# Each build reads its own shaders (SPECULA_SHADER_DIR). Prints one line per case and exits
# non-zero if any output differs.
set -uo pipefail
OLD="$1"
OLD_SHADERS="$2"
NEW="${3:-build/specula}"
ASSETS="$(cd "$(dirname "$0")/../.." && pwd)/shared/assets"
OUT="$(mktemp -d)"
trap 'rm -rf "$OUT"' EXIT
SIZE="--width 320 --height 180"
HELMET="$ASSETS/models/DamagedHelmet/DamagedHelmet.glb"
CASES=(
  "demo"
  "demo --msaa 1"
  "demo --bloom on"
  "demo --bloom on --msaa 1"
  "demo --auto-exposure on"
  "demo --fxaa on"
  "demo --fxaa on --msaa 1"
  "demo --ssao on"
  "demo --bloom on --ssao on --fxaa on --auto-exposure on"
  "demo --debug-view ssao"
  "demo --debug-view bloom"
  "demo --debug-view normal"
  "demo --debug-view brdf-d"
  "demo --shading blinn-phong"
  "demo --shading gouraud"
  "demo --brdf-g schlick-ggx --brdf-diffuse burley"
  "demo --gizmos"
  "learnopengl"
  "learnopengl-ibl --env $ASSETS/env/lobby_1k.hdr"
  "$HELMET --env $ASSETS/env/venice_1k.hdr"
  "$HELMET --env $ASSETS/env/venice_1k.hdr --bloom on --ssao on --fxaa on --auto-exposure on"
  "$HELMET --debug-view normal"
  "$ASSETS/models/AlphaBlendModeTest/AlphaBlendModeTest.glb"
  "$ASSETS/models/VertexColorTest/VertexColorTest.glb"
  "$ASSETS/models/NormalTangentMirrorTest/NormalTangentMirrorTest.glb"
  "doom"
  "doom --ssao on"
  "doom --shading pbr"
)
status=0
i=0
for c in "${CASES[@]}"; do
  for ext in png exr; do
    i=$((i + 1))
    # shellcheck disable=SC2086
    SPECULA_SHADER_DIR="$OLD_SHADERS" "$OLD" render $c $SIZE -o "$OUT/old-$i.$ext" >/dev/null 2>&1 || echo "old failed: $c"
    # shellcheck disable=SC2086
    "$NEW" render $c $SIZE -o "$OUT/new-$i.$ext" >/dev/null 2>"$OUT/err" || { echo "new failed: $c: $(tail -1 "$OUT/err")"; status=1; }
    if cmp -s "$OUT/old-$i.$ext" "$OUT/new-$i.$ext"; then
      echo "same      $ext  $c"
    else
      echo "DIFFERENT $ext  $c"
      status=1
    fi
  done
done
exit $status
