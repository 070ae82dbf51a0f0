#!/usr/bin/env bash
# Renders the images of the README and docs/ with the program itself (docs/images/).
set -euo pipefail
BUILD="${1:-build}"
SHARED="$(cd "$(dirname "$0")/.." && pwd)/../shared/assets"
OUT=docs/images
mkdir -p "$OUT"
S="$BUILD/specula render"
$S --width 960 --height 540 -o "$OUT/demo.png"
$S learnopengl --width 960 --height 540 -o "$OUT/learnopengl.png"
$S learnopengl-ibl --env "$SHARED/env/lobby_1k.hdr" --width 960 --height 540 -o "$OUT/learnopengl-ibl.png"
# The core set, lit by the default light rig only (no environment).
for model in DamagedHelmet/DamagedHelmet.glb WaterBottle/WaterBottle.gltf NormalTangentMirrorTest/NormalTangentMirrorTest.glb \
             AlphaBlendModeTest/AlphaBlendModeTest.glb TextureSettingsTest/TextureSettingsTest.glb OrientationTest/OrientationTest.glb; do
  name=$(basename "$model"); name=${name%.*}
  $S "$SHARED/models/$model" --env none --width 480 --height 360 -o "$OUT/$name.png"
done
# Image-based lighting from real HDRs.
$S "$SHARED/models/DamagedHelmet/DamagedHelmet.glb" --env "$SHARED/env/venice_1k.hdr" --width 480 --height 360 -o "$OUT/DamagedHelmet-venice.png"
$S "$SHARED/models/WaterBottle/WaterBottle.gltf" --env "$SHARED/env/studio_1k.hdr" --width 480 --height 360 -o "$OUT/WaterBottle-studio.png"
$S --env "$SHARED/env/sunset_1k.hdr" --width 480 --height 360 -o "$OUT/demo-sunset.png"
# Post-processing (docs/post-processing.md): bloom and SSAO, and the buffers alone.
$S --bloom on --ssao on --width 960 --height 540 -o "$OUT/demo-post.png"
$S --env none --bloom on --width 480 --height 270 -o "$OUT/demo-night-bloom.png"
$S --debug-view ssao --width 480 --height 270 -o "$OUT/demo-ssao.png"
$S --env none --debug-view bloom --width 480 --height 270 -o "$OUT/demo-bloom.png"
$S "$SHARED/models/DamagedHelmet/DamagedHelmet.glb" --env "$SHARED/env/venice_1k.hdr" --bloom on --ssao on --width 480 --height 360 -o "$OUT/DamagedHelmet-post.png"
$S "$SHARED/models/DamagedHelmet/DamagedHelmet.glb" --debug-view ssao --width 480 --height 360 -o "$OUT/DamagedHelmet-ssao.png"
# The shading-model galleries (docs/materials.md) and the Doom-era demo level.
G="$BUILD/specula gallery"
$G demo --width 360 --height 240 --columns 4 -o "$OUT/gallery-demo.png"
$G "$SHARED/models/DamagedHelmet/DamagedHelmet.glb" --width 300 --height 300 --columns 4 -o "$OUT/gallery-DamagedHelmet.png"
$G doom --env none --width 320 --height 200 --columns 4 -o "$OUT/gallery-doom.png"
$S doom --width 640 --height 400 -o "$OUT/doom.png"
# Shadows (docs/shadows.md): the models made to show them, beside their authors' screenshots
# (copied from the assets, CC BY 4.0), under a dim constant environment like the screenshots'.
for model in ShadowsDirectional/shadows-directional ShadowsSpot/shadows-spot; do
  name=$(dirname "$model")
  $S "$SHARED/models/$model.gltf" --env-color 0.1,0.1,0.1 --width 960 --height 540 -o "$OUT/$name.png"
  cp "$SHARED/models/$name/screenshot.png" "$OUT/$name-reference.png"
done
# Coloured and partial shadows (docs/shadows.md): glass, a glass volume and blended surfaces.
$S tests/assets/transparency/transmission.json --width 960 --height 540 -o "$OUT/tinted-shadows.png"
$S --debug-view shadow-atlas --width 540 --height 540 -o "$OUT/demo-shadow-atlas.png"
$S --debug-view cascades --width 480 --height 270 -o "$OUT/demo-cascades.png"
$S "$SHARED/models/BreakfastRoom/BreakfastRoom.gltf" --env none --width 480 --height 270 -o "$OUT/BreakfastRoom-sun.png"
