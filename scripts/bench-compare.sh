#!/usr/bin/env bash
# Interleaved before/after benchmark: `specula bench` of two builds, alternated over ROUNDS
# rounds so that both see the same machine load, then each scene's median frame times.
#   [NEW_FLAGS="--shadows off"] scripts/bench-compare.sh OLD_SPECULA OLD_SHADER_DIR [NEW_SPECULA] [ROUNDS]
# Scenes: learnopengl, learnopengl-ibl, demo (plain), DamagedHelmet with every post pass on.
# NEW_FLAGS: extra flags for the new build only (a feature the old one lacks, switched off).
set -u
OLD="$1"
OLD_SHADERS="$2"
NEW="${3:-build/specula}"
ROUNDS="${4:-3}"
ASSETS="$(cd "$(dirname "$0")/../.." && pwd)/shared/assets"
OUT="$(mktemp -d)"
trap 'rm -rf "$OUT"' EXIT
for round in $(seq "$ROUNDS"); do
  for who in old new; do
    if [ "$who" = old ]; then bin="$OLD"; shaders="$OLD_SHADERS"; flags=""; else bin="$NEW"; shaders=""; flags="${NEW_FLAGS:-}"; fi
    # shellcheck disable=SC2086 # flags are words
    SPECULA_SHADER_DIR="$shaders" "$bin" bench --scene learnopengl learnopengl-ibl demo --frames 15 --warmup 3 $flags \
      -o "$OUT/$who-plain-$round.json" >/dev/null 2>&1
    # shellcheck disable=SC2086
    SPECULA_SHADER_DIR="$shaders" "$bin" bench --scene "$ASSETS/models/DamagedHelmet/DamagedHelmet.glb" --frames 15 --warmup 3 \
      --bloom on --ssao on --fxaa on --auto-exposure on $flags -o "$OUT/$who-helmet-$round.json" >/dev/null 2>&1
  done
done
python3 - "$OUT" <<'PY'
import glob, json, os, sys
times = {}
for f in sorted(glob.glob(os.path.join(sys.argv[1], '*.json'))):
    who = os.path.basename(f).split('-')[0]
    for r in json.load(open(f))['results']:
        times.setdefault(os.path.basename(r['scene']), {}).setdefault(who, []).append(r['frameCpuMs']['median'])
print('scene: median ms per frame, one per round (old -> new)')
for scene, t in times.items():
    print(f"{scene}: {', '.join('%.0f' % v for v in t.get('old', []))} -> {', '.join('%.0f' % v for v in t.get('new', []))}")
PY
