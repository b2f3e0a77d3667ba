#!/usr/bin/env bash
# include_order.py fails on an include that runs back up, on a folder and on a header without a layer, on the viewer's
# app including its platform, and passes a tree that keeps the order (a tree made here, two layers).
set -uo pipefail
script="$(dirname "$0")/include_order.py"
t="$(mktemp -d)"; trap 'rm -rf "$t"' EXIT
mkdir -p "$t/core/low" "$t/core/high" "$t/core/include/essi"
printf 'low: low\nhigh: high\n' >"$t/core/LAYERS"
printf '#pragma once\n' >"$t/core/include/essi/low.hpp"
printf '#pragma once\n#include "essi/low.hpp"\n' >"$t/core/include/essi/high.hpp"
printf '#include "essi/low.hpp"\n' >"$t/core/low/low.cpp"
printf '#include "essi/high.hpp"\n#include "essi/low.hpp"\n' >"$t/core/high/high.cpp"
failures=0
out="$(python3 "$script" "$t")"; rc=$?
if [ $rc -eq 0 ]; then echo "ok   - a tree in order passes"; else echo "FAIL - a tree in order: $out"; failures=1; fi
printf '#include "essi/low.hpp"\n\n#include "essi/high.hpp"\n' >"$t/core/low/low.cpp"
out="$(python3 "$script" "$t")"; rc=$?
if [ $rc -eq 1 ] && grep -q "core/low/low.cpp:3: includes essi/high.hpp of layer 'high' from layer 'low'" <<<"$out"; then
  echo "ok   - an include against the order fails, with its file and line"
else echo "FAIL - include against the order: rc $rc: $out"; failures=1; fi
printf '#include "essi/low.hpp"\n' >"$t/core/low/low.cpp"
mkdir -p "$t/core/stray"
printf '#pragma once\n' >"$t/core/include/essi/orphan.hpp"
out="$(python3 "$script" "$t")"; rc=$?
if [ $rc -eq 1 ] && grep -q "core/stray/: no layer" <<<"$out" && grep -q "orphan.hpp: no layer" <<<"$out"; then
  echo "ok   - a folder and a header without a layer fail"
else echo "FAIL - no layer: rc $rc: $out"; failures=1; fi
rm -rf "$t/core/stray" "$t/core/include/essi/orphan.hpp"
mkdir -p "$t/web/app" "$t/web/platform"
printf '#include "app/App.hpp"\n' >"$t/web/platform/Main.cpp"
printf '#pragma once\n\n#include "platform/Platform.hpp"\n' >"$t/web/app/App.hpp"
out="$(python3 "$script" "$t")"; rc=$?
if [ $rc -eq 1 ] && grep -q "web/app/App.hpp:3: includes platform/Platform.hpp from web/app/" <<<"$out"; then
  echo "ok   - the viewer's app including its platform fails, with its file and line"
else echo "FAIL - app includes platform: rc $rc: $out"; failures=1; fi
printf '#pragma once\n' >"$t/web/app/App.hpp"
out="$(python3 "$script" "$t")"; rc=$?
if [ $rc -eq 0 ]; then echo "ok   - the platform including the app passes"; else echo "FAIL - platform includes app: $out"; failures=1; fi
exit $failures
