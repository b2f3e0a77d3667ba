#!/usr/bin/env bash
# scripts/setup installs what a make target needs, no more (its --list): `make native` no Emscripten, Chromium,
# LinuxCNC or clang; `make test` the browser and the reference programs; an unknown need is an error (exit 2).
set -uo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
failures=0
pass() { echo "ok   - $1"; }
fail() { echo "FAIL - $1"; failures=$((failures + 1)); }
has() { grep -qx -- "$2" <<<"$1"; }

native="$(bash "$root/scripts/setup" --list native)"
for p in emscripten chromium linuxcnc-uspace clang-14 xvfb; do
  if has "$native" "$p"; then fail "native installs $p"; else pass "native leaves out $p"; fi
done
for p in cmake ninja-build libcli11-dev nlohmann-json3-dev libcpp-httplib-dev libglfw3-dev libicu-dev libcairo2-dev libpango1.0-dev fonts-wqy-microhei; do
  if has "$native" "$p"; then pass "native installs $p"; else fail "native lacks $p"; fi
done
wasm="$(bash "$root/scripts/setup" --list wasm)"
if has "$wasm" emscripten && ! has "$wasm" chromium; then pass "wasm: emscripten, no chromium"; else fail "wasm: $wasm"; fi
test_list="$(bash "$root/scripts/setup" --list test)"
for p in emscripten chromium linuxcnc-uspace libpolyclipping-dev librsvg2-bin xvfb poppler-utils clang-format-14; do
  if has "$test_list" "$p"; then pass "test installs $p"; else fail "test lacks $p"; fi
done
dist="$(bash "$root/scripts/setup" --list dist)"
for p in emscripten lintian systemd libicu-dev; do
  if has "$dist" "$p"; then pass "dist installs $p"; else fail "dist lacks $p"; fi
done
if has "$dist" chromium; then fail "dist installs chromium"; else pass "dist leaves out chromium"; fi
if has "$test_list" lintian; then pass "test installs lintian (make test checks the packages)"; else fail "test lacks lintian"; fi
fuzz="$(bash "$root/scripts/setup" --list fuzz)"
if has "$fuzz" clang-14 && has "$fuzz" libclang-rt-14-dev; then pass "fuzz: clang-14"; else fail "fuzz: $fuzz"; fi
out="$(bash "$root/scripts/setup" nonsense 2>&1)"; rc=$?
if [ $rc -eq 2 ] && grep -q "expected native, wasm, test, fuzz, dist or all" <<<"$out"; then pass "unknown need: exit 2"
else fail "unknown need: rc $rc: $out"; fi
[ $failures -eq 0 ]
