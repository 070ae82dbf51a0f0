#!/usr/bin/env bash
# Runs the whole test suite (unit, gl, cli) with ctest. Windowed tests need a display:
# without one the suite runs under Xvfb.
set -euo pipefail
BUILD="${1:-build}"
cd "$BUILD"
args=(--output-on-failure --timeout 600 -j 2)
if [ -z "${DISPLAY:-}" ] && command -v xvfb-run >/dev/null; then
  exec xvfb-run -a -s "-screen 0 1280x1024x24" ctest "${args[@]}"
fi
exec ctest "${args[@]}"
