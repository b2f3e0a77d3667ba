#!/usr/bin/env bash
# The tarball of make dist: its essi is static and runs in an empty root (a folder holding nothing but the binary,
# entered with chroot): it checks every example as the native build does, prints its version, converts its
# Chinese text to a GB 18030 terminal (ICU, no gconv modules), and `essi serve` from there serves the viewer
# compiled into it (the page, the program gzip-encoded or not) and /api/check.
#   static_chroot.sh TARBALL NATIVE_ESSI WEB_DIR EXAMPLES_DIR
set -uo pipefail
tarball="$1" native="$2" web="$3" examples="$4"
failures=0
pass() { echo "ok   - $1"; }
fail() { echo "FAIL - $1"; failures=$((failures + 1)); }
for f in "$tarball" "$native" "$web/essi_viewer.wasm"; do
  [ -e "$f" ] || { echo "FAIL - $f not found (run make dist)"; exit 1; }
done
[ "$(id -u)" -eq 0 ] || { echo "FAIL - chroot needs root (CI runs as root)"; exit 1; }
command -v curl >/dev/null || { echo "FAIL - curl not found (scripts/setup test installs it)"; exit 1; }

work="$(mktemp -d)"
server=""
cleanup() { [ -n "$server" ] && kill "$server" 2>/dev/null; rm -rf "$work"; }
trap cleanup EXIT
tar -xzf "$tarball" -C "$work"
dir="$(find "$work" -mindepth 1 -maxdepth 1 -type d)"
for f in essi README.md LICENSE THIRD-PARTY-NOTICES.md CHANGELOG.md share/man/man1/essi.1 \
         share/completions/essi.bash share/completions/_essi share/completions/essi.fish; do
  if [ -e "$dir/$f" ]; then pass "tarball holds $f"; else fail "tarball lacks $f"; fi
done
case "$(basename "$tarball")" in
  essi-*-linux-x86_64.tar.gz) pass "name $(basename "$tarball")" ;;
  *) fail "name $(basename "$tarball") is not essi-<version>-linux-x86_64.tar.gz" ;;
esac
ldd_out="$(ldd "$dir/essi" 2>&1)"
if grep -q "not a dynamic executable" <<<"$ldd_out"; then pass "ldd: not a dynamic executable"; else fail "ldd: $ldd_out"; fi

root="$work/root"
mkdir -p "$root"
cp "$dir/essi" "$root/essi"
chroot_bin="$(command -v chroot)"
in_root() { env -i LANG=C.UTF-8 "$chroot_bin" "$root" /essi "$@"; }

version="$(in_root --version)"
if [[ "$version" =~ ^essi\ [0-9]+\.[0-9]+\.[0-9]+\ \(commit\ [0-9a-f]{12}\)$ ]] && [ "$version" = "$("$native" --version)" ]; then
  pass "--version in the empty root: $version"
else
  fail "--version: '$version' (native: '$("$native" --version)')"
fi

# Every example, from stdin (nothing but the binary in the root): the JSON report and the exit code of the
# native build, byte for byte.
n=0
for tape in "$examples"/*.esi "$examples"/*.eia; do
  name="$(basename "$tape")"
  args=(check --format json --input auto)
  [ -f "${tape%.*}.profile.json" ] && continue  # (a profile file would have to be in the root)
  static_out="$(in_root "${args[@]}" - <"$tape" 2>/dev/null)"; static_rc=$?
  native_out="$(env -i LANG=C.UTF-8 "$native" "${args[@]}" - <"$tape" 2>/dev/null)"; native_rc=$?
  if [ "$static_out" = "$native_out" ] && [ $static_rc -eq $native_rc ] && [ -n "$static_out" ]; then
    n=$((n + 1))
  else
    fail "$name: static (rc $static_rc) and native (rc $native_rc) differ"
  fi
done
[ $n -gt 20 ] && pass "$n examples checked in the empty root as natively" || fail "only $n examples agreed"

# The other commands from the binary alone, as natively (stdout byte for byte); PNG needs rsvg-convert, which the
# error names with its Debian package.
tape="$examples/kerf_parts.esi"
for cmd in "stats --format json -" "trace --kerf -" "trace --machine -" "convert --to eia -" "convert --to gcode -" \
           "profile list" "profile show woyda"; do
  # shellcheck disable=SC2086
  static_out="$(in_root $cmd <"$tape" 2>&1)"; static_rc=$?
  native_out="$(env -i LANG=C.UTF-8 "$native" $cmd <"$tape" 2>&1)"; native_rc=$?
  if [ "$static_out" = "$native_out" ] && [ $static_rc -eq $native_rc ] && [ -n "$static_out" ]; then
    pass "essi $cmd in the empty root (rc $static_rc)"
  else
    fail "essi $cmd: static rc $static_rc, native rc $native_rc: $(head -c 200 <<<"$static_out")"
  fi
done
in_root render -o /part.svg - <"$tape" >/dev/null 2>&1
env -i "$native" render -o "$work/part.svg" - <"$tape" >/dev/null 2>&1
if [ -s "$root/part.svg" ] && cmp -s "$root/part.svg" "$work/part.svg"; then pass "essi render to SVG in the empty root"
else fail "essi render to SVG differs or is missing"; fi
rm -f "$root/part.svg"
cp "$examples/kerf_values.esi" "$root/b.esi"
static_out="$(in_root diff --format json - /b.esi <"$tape" 2>&1)"; static_rc=$?
env -i "$native" diff --format json - "$root/b.esi" <"$tape" >"$work/diff.json" 2>&1; native_rc=$?
native_out="$(sed "s|$root/b.esi|/b.esi|g" "$work/diff.json")"
if [ "$static_out" = "$native_out" ] && [ $static_rc -eq $native_rc ]; then pass "essi diff in the empty root (rc $static_rc)"
else fail "essi diff: static rc $static_rc, native rc $native_rc"; fi
rm -f "$root/b.esi"
png="$(in_root render -o /part.png - <"$tape" 2>&1)"; rc=$?
if [ $rc -eq 2 ] && grep -q "librsvg2-bin" <<<"$png"; then pass "render to PNG without rsvg-convert names librsvg2-bin"
else fail "render to PNG: rc $rc $png"; fi

# Chinese terminals: the Chinese report in GB 18030 and GBK, converted by ICU inside the static binary (its data
# cut to the GB converters). The text summary ends in the run time, which differs from run to run: it is blanked.
tape="$examples/bad_character.esi"
without_time() { sed -E 's/[0-9]+\.[0-9]+ s$/T s/'; }
utf8="$(env -i LANG=C.UTF-8 "$native" check --lang zh - <"$tape" 2>/dev/null | without_time)"
for charset in GB18030 GBK; do
  out="$(env -i LANG=zh_CN.$charset "$chroot_bin" "$root" /essi check --lang zh - <"$tape" 2>/dev/null | without_time)"
  if [ "$(iconv -f "$charset" -t UTF-8 <<<"$out")" = "$utf8" ] && [ "$out" != "$utf8" ]; then
    pass "the Chinese report in $charset in the empty root"
  else
    fail "$charset terminal: $(head -c 200 <<<"$out" | od -c | head -4)"
  fi
done

# essi serve from the empty root: the embedded viewer and the API.
env -i "$chroot_bin" "$root" /essi serve --host 127.0.0.1 --port 0 --data /data >"$work/serve.log" 2>&1 &
server=$!
url=""
for _ in $(seq 1 100); do
  url="$(grep -o 'http://127.0.0.1:[0-9]*/' "$work/serve.log" | head -1)"
  [ -n "$url" ] && break
  sleep 0.1
done
if [ -z "$url" ]; then
  fail "essi serve did not start: $(cat "$work/serve.log")"
else
  pass "essi serve in the empty root: $(head -1 "$work/serve.log")"
  curl -s -D "$work/h" -o "$work/index.html" "$url"
  if grep -q "^HTTP/1.1 200" "$work/h" && grep -qi "^Content-Security-Policy:" "$work/h" && grep -q "essi_viewer.js" "$work/index.html"; then
    pass "GET / : the viewer's page with its CSP"
  else
    fail "GET /: $(head -3 "$work/h")"
  fi
  curl -s -H "Accept-Encoding: gzip" -D "$work/h" -o "$work/wasm.gz" "${url}essi_viewer.wasm"
  if grep -qi "^Content-Encoding: gzip" "$work/h" && grep -qi "^Content-Type: application/wasm" "$work/h" \
     && gunzip -c "$work/wasm.gz" | cmp -s - "$web/essi_viewer.wasm"; then
    pass "GET /essi_viewer.wasm with gzip: gzip-encoded, the built program"
  else
    fail "wasm with gzip: $(tr -d '\r' <"$work/h" | head -8)"
  fi
  curl -s -D "$work/h" -o "$work/wasm" "${url}essi_viewer.wasm"
  if ! grep -qi "^Content-Encoding" "$work/h" && cmp -s "$work/wasm" "$web/essi_viewer.wasm"; then
    pass "GET /essi_viewer.wasm without gzip: the program as built"
  else
    fail "wasm without gzip: $(tr -d '\r' <"$work/h" | head -8)"
  fi
  for f in essi_viewer.js share_store.js; do
    code="$(curl -s -o /dev/null -w '%{http_code}' "$url$f")"
    [ "$code" = 200 ] && pass "GET /$f: 200" || fail "GET /$f: $code"
  done
  tape="$examples/bad_arc_off_circle.esi"
  api="$(curl -s -H "Content-Type: application/octet-stream" --data-binary @"$tape" "${url}api/check")"
  if python3 -c 'import json,sys; d=json.loads(sys.argv[1]); sys.exit(0 if any(x["code"]=="E301" or x["severity"]=="error" for x in d["files"][0]["diagnostics"]) else 1)' "$api" 2>/dev/null; then
    pass "POST /api/check: the report with the tape's error"
  else
    fail "POST /api/check: $(head -c 300 <<<"$api")"
  fi
fi
[ $failures -eq 0 ]
