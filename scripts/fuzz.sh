#!/usr/bin/env bash
# Runs the libFuzzer fuzzers of a SPECULA_FUZZERS build (docs/testing.md#fuzzers).
#   scripts/fuzz.sh BUILD [SECONDS]        each fuzzer for SECONDS (default 15): CI's short run
#   scripts/fuzz.sh BUILD --runs N         each fuzzer for N executions (the recorded long run)
#   FUZZERS="fuzz_hdr fuzz_exr" scripts/fuzz.sh ...   only these
# Each fuzzer's working corpus is BUILD/fuzz-corpus/<name>, seeded from fuzz/seeds/<name> and
# ../shared/assets; it grows between runs. A crash, leak, timeout (10 s) or out-of-memory
# (2.5 GiB) fails the script and leaves the input as BUILD/fuzz-artifacts/<name>/crash-*:
# reproduce with BUILD/fuzz/<name> FILE. A summary line per fuzzer goes to BUILD/fuzz-summary.txt.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD="${1:?usage: scripts/fuzz.sh BUILD [SECONDS | --runs N]}"
shift
limit=(-max_total_time="${1:-15}")
if [ "${1:-}" = "--runs" ]; then limit=(-runs="${2:?--runs N}"); fi
ASSETS=../shared/assets
FUZZERS="${FUZZERS:-fuzz_gltf fuzz_glb fuzz_scene fuzz_hdr fuzz_exr fuzz_texture fuzz_cli}"
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:allocator_may_return_null=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}"

seed() { # name, then files or directories to copy into its corpus
  local name="$1"; shift
  local corpus="$BUILD/fuzz-corpus/$name"
  mkdir -p "$corpus"
  cp -n fuzz/seeds/"${name#fuzz_}"/* "$corpus"/ 2>/dev/null || true
  for f in "$@"; do [ -f "$f" ] && cp -n "$f" "$corpus"/ || true; done
}

: > "$BUILD/fuzz-summary.txt"
status=0
for name in $FUZZERS; do
  dict=() max_len=8192
  case "$name" in
    # The hand-made test assets (animation, material extensions, variants) too.
    fuzz_gltf) seed "$name" $(find "$ASSETS/models" tests/assets/gltf -name '*.gltf' -size -200k); dict=(-dict=fuzz/dict/gltf.dict); max_len=16384 ;;
    # The compressed test models (Draco in the assets, meshopt and WebP in tests/assets/gltf)
    # take the decoders' paths.
    fuzz_glb) seed "$name" $(find "$ASSETS/models" tests/assets/gltf -name '*.glb' -size -200k); dict=(-dict=fuzz/dict/gltf.dict); max_len=65536 ;;
    fuzz_scene) seed "$name"; dict=(-dict=fuzz/dict/scene.dict) ;;
    fuzz_hdr) seed "$name" "$ASSETS/env/venice_1k.hdr"; max_len=16384 ;;   # the asset is cut to max_len
    fuzz_exr) seed "$name" "$ASSETS"/env/*.exr; max_len=262144 ;;
    fuzz_texture) seed "$name" $(find "$ASSETS/models" \( -iname '*.png' -o -iname '*.jpg' \) -size -64k); max_len=65536 ;;
    fuzz_cli) seed "$name"; dict=(-dict=fuzz/dict/cli.dict); max_len=512 ;;
  esac
  artifacts="$BUILD/fuzz-artifacts/$name"
  mkdir -p "$artifacts"
  log="$BUILD/fuzz-$name.log"
  echo "fuzz: $name (${limit[*]})" >&2
  if "$BUILD/fuzz/$name" "$BUILD/fuzz-corpus/$name" "${dict[@]}" "${limit[@]}" -max_len="$max_len" -timeout=10 \
       -rss_limit_mb=2560 -malloc_limit_mb=2560 -print_final_stats=1 -artifact_prefix="$artifacts/" >"$log" 2>&1; then
    runs=$(sed -n 's/^Done \([0-9]*\) runs in \([0-9]*\) second.*/\1 runs in \2 s/p' "$log" | tail -1)
    cov=$(grep -o 'cov: [0-9]* ft: [0-9]* corp: [0-9]*/[0-9]*[a-zA-Z]*' "$log" | tail -1)
    echo "$name: $runs, $cov, no findings" | tee -a "$BUILD/fuzz-summary.txt" >&2
  else
    echo "$name: FAILED, see $log and $artifacts" | tee -a "$BUILD/fuzz-summary.txt" >&2
    grep -m3 -E 'ERROR|SUMMARY|Test unit written' "$log" >&2 || true
    status=1
  fi
done
exit $status
