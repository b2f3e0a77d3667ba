#!/usr/bin/env bash
# `essi serve` over real HTTP (curl): every endpoint and every error case. Usage: serve_api.sh PATH/TO/essi
# Starts the server on a free loopback port (--port 0; the address is read from its first output line) with a
# stand-in viewer folder, a data folder and a small --max-body, and stops it at the end.
set -uo pipefail
essi="${1:?usage: serve_api.sh ESSI}"
root="$(cd "$(dirname "$0")/../.." && pwd)"
tmp="$(mktemp -d)"
server_pid=""
cleanup() { if [ -n "$server_pid" ]; then kill "$server_pid" 2>/dev/null; wait "$server_pid" 2>/dev/null; fi; rm -rf "$tmp"; }
trap cleanup EXIT

failures=0
pass() { echo "ok   - $1"; }
fail() { echo "FAIL - $1"; failures=$((failures + 1)); }
# expect NAME STATUS_WANTED BODY_REGEX -- curl args...
expect() {
  local name="$1" want="$2" regex="$3"; shift 3; [ "$1" = "--" ] && shift
  local body code
  body="$(curl -sS -o "$tmp/body" -w '%{http_code}' -H 'Expect:' "$@")" || { fail "$name: curl failed"; return; }
  code="$body"; body="$(cat "$tmp/body")"
  if [ "$code" != "$want" ]; then fail "$name: HTTP $code, expected $want (body: ${body:0:300})"; return; fi
  if ! grep -Eq -- "$regex" <<<"$body"; then fail "$name: body does not match /$regex/: ${body:0:300}"; return; fi
  pass "$name ($code)"
}

mkdir -p "$tmp/web" "$tmp/examples" "$tmp/outside"
echo '<!doctype html><title>stand-in viewer</title>' > "$tmp/web/index.html"
echo 'not really wasm' > "$tmp/web/essi_viewer.wasm"
gzip -9 -n -k "$tmp/web/essi_viewer.wasm"  # (its gzip twin, as the build makes it)
cp "$root/examples/absolute_offset.esi" "$tmp/examples/"
echo 'SECRET-OUTSIDE' > "$tmp/outside/secret.txt"
echo 'SECRET-OUTSIDE' > "$tmp/secret.txt"

"$essi" serve --host 127.0.0.1 --port 0 --web-root "$tmp/web" --examples "$tmp/examples" --data "$tmp/data" \
  --max-body 64KB > "$tmp/out.log" 2> "$tmp/err.log" &
server_pid=$!
url=""
for _ in $(seq 1 100); do
  url="$(grep -o 'http://127\.0\.0\.1:[0-9]*' "$tmp/out.log" 2>/dev/null | head -1)"
  [ -n "$url" ] && break
  kill -0 "$server_pid" 2>/dev/null || break
  sleep 0.05
done
if [ -z "$url" ]; then echo "FAIL - server did not start"; cat "$tmp/out.log" "$tmp/err.log"; exit 1; fi
echo "# server at $url (pid $server_pid)"

tape="$root/examples/absolute_offset.esi"
bad="$root/examples/bad_arc_off_circle.esi"

# --- static files ----------------------------------------------------------------------------------------
expect "viewer index" 200 'stand-in viewer' -- "$url/"
expect "example tape" 200 '^' -- "$url/examples/absolute_offset.esi"
expect "example list" 200 '\["absolute_offset.esi"\]' -- "$url/examples/index.json"
expect "missing file is a JSON 404" 404 '"error"' -- "$url/nothere.js"
# The program: gzip-encoded (its twin) for a client that takes gzip, as it is for one that does not.
headers="$(curl -sS -D - -o "$tmp/wasm.gz" -H 'Accept-Encoding: gzip, deflate, br' "$url/essi_viewer.wasm")"
if grep -qi '^content-encoding: gzip' <<<"$headers" && [ "$(gunzip -c "$tmp/wasm.gz")" = 'not really wasm' ] &&
   grep -qi '^vary: accept-encoding' <<<"$headers"; then pass "essi_viewer.wasm gzip-encoded for gzip clients"
else fail "essi_viewer.wasm with Accept-Encoding: gzip: $headers"; fi
headers="$(curl -sS -D - -o "$tmp/wasm" "$url/essi_viewer.wasm")"
if ! grep -qi '^content-encoding' <<<"$headers" && [ "$(cat "$tmp/wasm")" = 'not really wasm' ]; then
  pass "essi_viewer.wasm as it is without Accept-Encoding"
else fail "essi_viewer.wasm without Accept-Encoding: $headers"; fi
# Paths that try to leave the served folders: never the file's content.
for p in '/../secret.txt' '/%2e%2e/secret.txt' '/%2E%2E/%2e%2e/secret.txt' '/examples/../../secret.txt' \
         '/examples/..%2f..%2fsecret.txt' '/examples/%2e%2e/%2e%2e/outside/secret.txt' '/..%5csecret.txt' \
         '/examples/....//secret.txt'; do
  code="$(curl -sS --path-as-is -o "$tmp/body" -w '%{http_code}' "$url$p")"
  if grep -q SECRET-OUTSIDE "$tmp/body" || [ "$code" = 200 ]; then fail "traversal $p: HTTP $code leaked"; else pass "traversal $p ($code)"; fi
done

# --- /api/health ---------------------------------------------------------------------------------------------
expect "health" 200 '"max_body":65536.*"ok":true' -- "$url/api/health"

# --- /api/check ----------------------------------------------------------------------------------------------
expect "check ok tape" 200 '"ok": true' -- --data-binary @"$tape" "$url/api/check"
expect "check bad tape: E301" 200 '"code": "E301"' -- --data-binary @"$bad" "$url/api/check?profile=iso6582&name=bad.esi"
expect "check names the file" 200 '"path": "bad.esi"' -- --data-binary @"$bad" "$url/api/check?name=bad.esi"
expect "check woyda profile" 200 '"profile": "woyda"' -- --data-binary @"$tape" "$url/api/check?profile=woyda"
printf 'N1 G90 G71\nN2 G00 X10 Y10\nN3 M03\nN4 G01 X50\nN5 M05\nN6 M30\n' > "$tmp/din.eia"
expect "check an EIA tape: input eia" 200 '"input": "eia"' -- --data-binary @"$tmp/din.eia" "$url/api/check?profile=din66025"
expect "check profile=auto names the dialect" 200 '"profile": "din66025"' -- --data-binary @"$tmp/din.eia" "$url/api/check?profile=auto"
expect "check profile=auto gives the evidence" 200 'din66025: `G90` absolute dimensions' -- --data-binary @"$tmp/din.eia" "$url/api/check?profile=auto"
expect "check input=essi reads EIA as ESSI: E101" 200 '"code": "E101"' -- --data-binary @"$tmp/din.eia" "$url/api/check?input=essi"
expect "check unknown input: 400" 400 '"error":"unknown input' -- --data-binary @"$tmp/din.eia" "$url/api/check?input=dxf"
expect "convert to gcode" 200 'G17 G21 G40 G90 G91.1 G94' -- --data-binary @"$tmp/din.eia" "$url/api/convert?to=gcode&profile=auto&absolute=1"
expect "convert to woyda EIA" 200 'G91' -- --data-binary @"$tmp/din.eia" "$url/api/convert?to=eia&to_profile=woyda&profile=auto"
expect "convert format=json" 200 '"diagnostics":' -- --data-binary @"$tmp/din.eia" "$url/api/convert?to=essi&profile=auto&format=json"
expect "convert without to: 400" 400 'expected essi, eia or gcode' -- --data-binary @"$tmp/din.eia" "$url/api/convert"
expect "convert a tape with errors: 422" 422 '"E119"' -- --data-binary @"$bad" "$url/api/convert?to=gcode&input=eia"
expect "convert a tape the cut plan rejects (E605): 422" 422 '"code":"E605"' -- --data-binary @"$root/examples/plan_collision.esi" "$url/api/convert?to=gcode"
expect "convert it with force=1: 200" 200 '^G17 G21' -- --data-binary @"$root/examples/plan_collision.esi" "$url/api/convert?to=gcode&force=1"
printf '+10+0 \n+10+0 \n+10+0 \n+10+0 \n64\n' > "$tmp/blanks.esi"
expect "check max_per_code=1: one W109 and the count of the rest" 200 '3 more W109 diagnostics not listed \(at most 1 of a code' -- --data-binary @"$tmp/blanks.esi" "$url/api/check?max_per_code=1"
expect "check max_per_code=x: 400" 400 "max_per_code='x': expected a whole number from 0 to 1000000000" -- --data-binary @"$tmp/blanks.esi" "$url/api/check?max_per_code=x"
expect "check empty body: E113" 200 '"code": "E113"' -- -X POST -H 'Content-Length: 0' -H 'Content-Type: application/octet-stream' "$url/api/check"
expect "check unknown profile: 400" 400 '"error":"unknown profile' -- --data-binary @"$tape" "$url/api/check?profile=nope"
expect "check profile is never a file: 400" 400 'unknown profile' -- --data-binary @"$tape" "$url/api/check?profile=/etc/passwd"
expect "check GET: 405" 405 '"error"' -- "$url/api/check"
head -c 70000 /dev/zero | tr '\0' '1' > "$tmp/big.esi"
expect "check body over --max-body: 413" 413 '"error":"request body too large' -- --data-binary @"$tmp/big.esi" "$url/api/check"
expect "chunked body over --max-body: 413" 413 '"error"' -- -H 'Transfer-Encoding: chunked' --data-binary @"$tmp/big.esi" "$url/api/check"
expect "unknown API path: 404" 404 '"error":"no API endpoint' -- "$url/api/nothing"

# A tape saved as UTF-16 with a byte order mark is read as its text, as `essi check` reads the file.
{ printf '\xFF\xFE'; iconv -f UTF-8 -t UTF-16LE "$bad"; } > "$tmp/utf16le.esi"
curl -sS -H 'Expect:' --data-binary @"$bad" "$url/api/check" > "$tmp/utf8.json"
curl -sS -H 'Expect:' --data-binary @"$tmp/utf16le.esi" "$url/api/check" > "$tmp/utf16.json"
if grep -q '"code"' "$tmp/utf8.json" && cmp -s "$tmp/utf8.json" "$tmp/utf16.json"; then pass "check a UTF-16 LE tape: the UTF-8 tape's report"
else fail "check a UTF-16 LE tape: the report differs from the UTF-8 tape's"; diff "$tmp/utf8.json" "$tmp/utf16.json" | head; fi
printf '\xFF\xFEx' > "$tmp/odd16.esi"
expect "check UTF-16 of an odd number of bytes: 400" 400 'UTF-16' -- --data-binary @"$tmp/odd16.esi" "$url/api/check"
expect "convert a UTF-16 LE tape with errors: 422" 422 '"E119"' -- --data-binary @"$tmp/utf16le.esi" "$url/api/convert?to=gcode&input=eia"

# The API's report is the CLI's report (same JSON, same path when named "-").
curl -sS -H 'Expect:' --data-binary @"$bad" "$url/api/check" > "$tmp/api.json"
"$essi" check --format json - < "$bad" > "$tmp/cli.json" 2>/dev/null
if cmp -s "$tmp/api.json" "$tmp/cli.json"; then pass "API report == essi check --format json -"; else fail "API report differs from the CLI's"; diff "$tmp/api.json" "$tmp/cli.json" | head; fi

# --- /api/share ----------------------------------------------------------------------------------------------
id="$(sha256sum "$tape" | cut -c1-64)"
expect "share: 201 with id and url" 201 "\"id\":\"$id\".*\"url\":\"/#share=$id\"" -- --data-binary @"$tape" "$url/api/share"
expect "share again: 200, not created" 200 '"created":false' -- --data-binary @"$tape" "$url/api/share"
curl -sS -o "$tmp/got.esi" "$url/api/share/$id"
if cmp -s "$tmp/got.esi" "$tape"; then pass "share round trip (byte for byte)"; else fail "share round trip differs"; fi
printf '\x00\xff\r\n+1+1\n' > "$tmp/bin.esi"
bid="$(sha256sum "$tmp/bin.esi" | cut -c1-64)"
expect "share binary bytes" 201 "\"id\":\"$bid\"" -- --data-binary @"$tmp/bin.esi" "$url/api/share"
curl -sS -o "$tmp/gotbin" "$url/api/share/$bid"
if cmp -s "$tmp/gotbin" "$tmp/bin.esi"; then pass "binary round trip"; else fail "binary round trip differs"; fi
expect "share unknown id: 404" 404 '"error":"no shared tape' -- "$url/api/share/$(printf nothing | sha256sum | cut -c1-64)"
expect "share bad id: 400" 400 '"error":"bad share id' -- "$url/api/share/abc"
expect "share upper-case id: 400" 400 '"error"' -- "$url/api/share/$(tr a-f A-F <<<"$id")"
expect "share id with traversal: JSON 404" 404 '"error"' -- --path-as-is "$url/api/share/..%2f..%2fsecret.txt"
expect "share empty body: 400" 400 '"error"' -- -X POST -H 'Content-Length: 0' -H 'Content-Type: application/octet-stream' "$url/api/share"
expect "share body over --max-body: 413" 413 '"error":"request body too large' -- --data-binary @"$tmp/big.esi" "$url/api/share"
expect "share GET list: 405" 405 '"error"' -- "$url/api/share"
expect "share DELETE without token: 403" 403 '"error"' -- -X DELETE "$url/api/share/$id"
expect "share POST to an id: 405" 405 '"error"' -- -H 'Content-Type: application/octet-stream' --data-binary x "$url/api/share/$id"
expect "bad request line: 400" 400 '' -- -X 'GET /x' "$url/"

# Persistence: a new server on the same data folder still has the tape.
kill "$server_pid"; wait "$server_pid" 2>/dev/null; server_pid=""
"$essi" serve --port 0 --web-root "$tmp/web" --data "$tmp/data" > "$tmp/out2.log" 2>&1 &
server_pid=$!
url=""
for _ in $(seq 1 100); do url="$(grep -o 'http://127\.0\.0\.1:[0-9]*' "$tmp/out2.log" | head -1)"; [ -n "$url" ] && break; sleep 0.05; done
expect "share survives a restart" 200 'ESSI|^' -- "$url/api/share/$id"
curl -sS -o "$tmp/got2.esi" "$url/api/share/$id"; cmp -s "$tmp/got2.esi" "$tape" && pass "restart round trip" || fail "restart round trip"
ls "$tmp/data"/*.tmp 2>/dev/null && fail "temporary files left in the data folder" || pass "no temporary files in the data folder"

# Errors at start: the viewer missing.
"$essi" serve --port 0 --web-root "$tmp/nothere" --data "$tmp/data" > /dev/null 2> "$tmp/err3.log"; rc=$?
[ $rc -eq 2 ] && grep -q 'viewer is not built' "$tmp/err3.log" && pass "no viewer: exit 2" || fail "no viewer: rc=$rc"
echo "# $failures failure(s)"
[ $failures -eq 0 ]
