#!/usr/bin/env bash
# Renders the README's images with the program itself (docs/images/).
set -euo pipefail
BUILD="${1:-build}"
ASSETS="$(cd "$(dirname "$0")/.." && pwd)/../shared/assets/models"
OUT=docs/images
mkdir -p "$OUT"
S="$BUILD/specula render"
$S --width 960 --height 540 -o "$OUT/demo.png"
$S learnopengl --width 960 --height 540 -o "$OUT/learnopengl.png"
for model in DamagedHelmet/DamagedHelmet.glb WaterBottle/WaterBottle.gltf NormalTangentMirrorTest/NormalTangentMirrorTest.glb \
             AlphaBlendModeTest/AlphaBlendModeTest.glb TextureSettingsTest/TextureSettingsTest.glb OrientationTest/OrientationTest.glb; do
  name=$(basename "$model"); name=${name%.*}
  $S "$ASSETS/$model" --width 480 --height 360 -o "$OUT/$name.png"
done
