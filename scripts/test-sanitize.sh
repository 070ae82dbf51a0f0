#!/usr/bin/env bash
# The whole test suite on the sanitizer build (make test-sanitize): any AddressSanitizer,
# LeakSanitizer or UndefinedBehaviorSanitizer report fails the test it happens in, in the test
# binaries and in every specula process the CLI tests start (they inherit these settings).
# Suppressions (scripts/sanitizers/) cover third-party code only, each with its reason.
set -euo pipefail
BUILD="${1:-build-sanitize}"
SUPP="$(cd "$(dirname "$0")" && pwd)/sanitizers"
# intercept_tls_get_addr=0: up to LLVM 16 (Debian 12 has clang 14) the runtime's __tls_get_addr
# interceptor takes a dynamic TLS block that happens to start 16 bytes past a page boundary for a
# pre-2.25 glibc header and reads the words before it as a block's bounds; LeakSanitizer's tracer
# then dies at exit ("Tracer caught signal 11"), no leak reported. Mesa's driver threads allocate
# such blocks, so it struck the cluster tests now and then. Fixed upstream in LLVM 17.
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0:strict_string_checks=1:check_initialization_order=1:detect_stack_use_after_return=1:intercept_tls_get_addr=0"
export LSAN_OPTIONS="suppressions=$SUPP/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:suppressions=$SUPP/ubsan.supp"
exec bash "$(dirname "$0")/test.sh" "$BUILD"
