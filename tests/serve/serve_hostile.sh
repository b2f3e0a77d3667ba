#!/usr/bin/env bash
# `essi serve` against hostile pages and requests (docs/security.md): Host (DNS rebinding), cross-origin writes,
# Content-Type, invalid UTF-8 and NUL, bodies never parsed as form parameters, security headers and the CSP,
# one Cache-Control, the static allow-list, a busy port. Usage: serve_hostile.sh PATH/TO/essi
essi="${1:?usage: serve_hostile.sh ESSI}"
source "$(dirname "$0")/lib.sh"
make_web_root
start_server main --data "$tmp/data" --allowed-host essi.lan --max-body 1MB
port="${url##*:}"
tape="$root/examples/absolute_offset.esi"
id="$(sha256sum "$tape" | cut -c1-64)"
oct=(-H 'Content-Type: application/octet-stream')

# --- Host (DNS rebinding) -------------------------------------------------------------------------------------
expect "Host of another name: 403" 403 '"error":"Host .evil.example. is not served' -- -H 'Host: evil.example' "$url/api/health"
expect "Host of another name on the page: 403" 403 '"error"' -- -H "Host: evil.example:$port" "$url/"
expect "Host localhost: 200" 200 '"ok":true' -- -H "Host: localhost:$port" "$url/api/health"
expect "Host of the bound address: 200" 200 '"ok":true' -- "$url/api/health"
expect "--allowed-host name: 200" 200 '"ok":true' -- -H "Host: ESSI.lan:$port" "$url/api/health"
expect "no Host header: 400" 400 '"error":"a Host header' -- -H 'Host:' "$url/api/health"

# --- cross-origin writes --------------------------------------------------------------------------------------
expect "cross-origin text/plain POST: 403" 403 '"error":"cross-origin' -- -H 'Origin: http://evil.example' -H 'Content-Type: text/plain' --data-binary @"$tape" "$url/api/share"
expect "... and nothing was stored" 404 '"error"' -- "$url/api/share/$id"
expect "Origin null: 403" 403 '"error"' -- -H 'Origin: null' -H 'Content-Type: text/plain' --data-binary @"$tape" "$url/api/share"
expect "Sec-Fetch-Site cross-site: 403" 403 '"error"' -- -H 'Sec-Fetch-Site: cross-site' "${oct[@]}" --data-binary @"$tape" "$url/api/check"
expect "cross-origin DELETE: 403" 403 '"error"' -- -X DELETE -H 'Origin: http://evil.example' "$url/api/share/$id"
head -c 2000000 /dev/zero | tr '\0' '1' > "$tmp/large.esi"
code="$(curl -sS -o "$tmp/body" -w '%{http_code} %{size_upload}' -H 'Origin: http://evil.example' -H 'Content-Type: text/plain' --data-binary @"$tmp/large.esi" "$url/api/share")"
[ "${code% *}" = 403 ] && [ "${code#* }" -lt 2000000 ] && pass "cross-origin 2 MB POST with Expect: 100-continue: 403 before the body (sent ${code#* } bytes)" || fail "Expect: 100-continue refusal: $code"
expect "same-origin text/plain POST: 201" 201 '"delete_token":"[0-9a-f]{64}"' -- -H "Origin: $url" -H 'Content-Type: text/plain' --data-binary @"$tape" "$url/api/share"
expect "POST without Content-Type: 415" 415 '"error":"POST needs Content-Type' -- -H 'Content-Type:' --data-binary @"$tape" "$url/api/check"
expect "multipart POST: 415" 415 '"error"' -- -F "tape=@$tape" "$url/api/share"
curl -sS -D "$tmp/headers" -o /dev/null -X OPTIONS -H 'Origin: http://evil.example' -H 'Access-Control-Request-Method: POST' "$url/api/share"
[ "$(header_count Access-Control-Allow-Origin)" = 0 ] && pass "no CORS on a preflight" || fail "a preflight got CORS headers"

# --- invalid UTF-8 and NUL: 400 JSON, never an exception text ---------------------------------------------------
for q in '/api/share/%ff%fe' '/api/check?profile=%ff' '/api/check?name=%c3%28' '/api/check?name=a%00b' '/api/check?profile=%ed%a0%80' '/index.html%00.esi' '/%ff'; do
  expect "bad bytes in $q: 400" 400 '"error":"the path or a query parameter is not valid UTF-8' -- "${oct[@]}" --data-binary @"$tape" --path-as-is "$url$q"
  grep -qi 'EXCEPTION_WHAT\|type_error\|json.exception' "$tmp/headers" "$tmp/body" && fail "$q: exception text leaked" || pass "$q: no exception text"
done
expect "GET /index.html%00.esi: 400" 400 '"error"' -- --path-as-is "$url/index.html%00.esi"
expect "valid UTF-8 name is kept" 200 '"path": "é.esi"' -- "${oct[@]}" --data-binary @"$tape" "$url/api/check?name=%C3%A9.esi"

# --- bodies are bytes, never form parameters --------------------------------------------------------------------
{ echo 'profile=woyda&name=x'; head -c 20000 /dev/zero | tr '\0' '1'; } > "$tmp/form.esi"
expect "form-encoded body over 8192 bytes: checked (curl's default type)" 200 '"profile": "iso6582"' -- --data-binary @"$tmp/form.esi" "$url/api/check"
expect "a body profile=woyda does not switch the profile" 200 '"profile": "iso6582"' -- --data-binary 'profile=woyda' "$url/api/check"
expect "... the query string does" 200 '"profile": "woyda"' -- --data-binary @"$tape" "$url/api/check?profile=woyda"
head -c 1100000 /dev/zero | tr '\0' '1' > "$tmp/big.esi"
expect "body over --max-body: 413 with the real limit" 413 '"error":"request body too large: the limit is 1048576 bytes' -- "${oct[@]}" --data-binary @"$tmp/big.esi" "$url/api/check"

# --- headers ------------------------------------------------------------------------------------------------------
expect "share download" 200 '' -- "$url/api/share/$id"
[ "$(header_count Cache-Control)" = 1 ] && pass "share download: one Cache-Control" || fail "share download: $(header_count Cache-Control) Cache-Control headers"
expect "viewer page" 200 'stand-in viewer' -- "$url/"
csp="$(header_value Content-Security-Policy)"
script_hash="'sha256-$(printf '\nconsole.log(1);\n' | openssl dgst -sha256 -binary | base64)'"
style_hash="'sha256-$(printf 'body{margin:0}' | openssl dgst -sha256 -binary | base64)'"
handler_hash="'sha256-$(printf 'event.preventDefault()' | openssl dgst -sha256 -binary | base64)'"
for part in "default-src 'none'" "'wasm-unsafe-eval'" "frame-ancestors 'none'" "$script_hash" "$style_hash" "'unsafe-hashes' $handler_hash"; do
  [[ "$csp" == *"$part"* ]] && pass "CSP has $part" || fail "CSP lacks $part: $csp"
done
[[ "$csp" != *"unsafe-inline"* && "$csp" != *"'unsafe-eval'"* ]] && pass "CSP allows no unsafe-inline/unsafe-eval" || fail "CSP too wide: $csp"
for h in 'X-Frame-Options: DENY' 'Referrer-Policy: no-referrer' 'Cross-Origin-Opener-Policy: same-origin' \
         'Cross-Origin-Embedder-Policy: require-corp' 'X-Content-Type-Options: nosniff' 'Cache-Control: no-cache'; do
  grep -qi "^$h" "$tmp/headers" && pass "page: $h" || fail "page lacks $h"
done
expect "API 404" 404 '"error"' -- "$url/api/nothing"
grep -qi '^X-Frame-Options: DENY' "$tmp/headers" && [ "$(header_count Cache-Control)" = 1 ] && pass "errors get the headers too" || fail "error response headers"

# --- the static allow-list ----------------------------------------------------------------------------------------
expect "viewer js" 200 'viewer' -- "$url/essi_viewer.js"
expect "example" 200 '^' -- "$url/examples/absolute_offset.esi"
expect "build tree file: 404" 404 '"error":"not found"' -- "$url/cmake_install.cmake"
grep -q "$root" "$tmp/body" && fail "build tree leaked the source path" || pass "no source path leaked"
expect "build tree folder: 404" 404 '"error"' -- "$url/CMakeFiles/secret.txt"

# --- an exception in a handler: a generic 500, its text only in the log --------------------------------------------
# With a --max-body of 2 PB, a declared Content-Length of 1 PB makes reserving the body throw std::bad_alloc.
stop_server
start_server huge --data "$tmp/data" --max-body 2251799813685248
exec 3<>"/dev/tcp/127.0.0.1/${url##*:}"
printf 'POST /api/check HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/octet-stream\r\nContent-Length: 1125899906842624\r\n\r\n' >&3
timeout 10 cat <&3 > "$tmp/raw"; exec 3<&-
head -1 "$tmp/raw" | grep -q '^HTTP/1.1 500' && grep -q '{"error":"internal error","status":500}' "$tmp/raw" && pass "exception: generic JSON 500" || fail "exception: $(head -c 300 "$tmp/raw")"
grep -qi 'bad_alloc\|EXCEPTION_WHAT' "$tmp/raw" && fail "exception text leaked to the client" || pass "exception text not in the response"
grep -q 'internal error: std::bad_alloc' "$tmp/huge.err" && pass "exception text in the log" || fail "exception not logged"
expect "server still answers after the exception" 200 '"ok":true' -- "$url/api/health"
port="${url##*:}"

# --- a busy port is an error at start-up ---------------------------------------------------------------------------
"$essi" serve --host 127.0.0.1 --port "$port" --web-root "$tmp/web" --data "$tmp/data2" > "$tmp/second.out" 2> "$tmp/second.err" &
second=$!
for _ in $(seq 1 100); do kill -0 "$second" 2>/dev/null || break; sleep 0.05; done
if kill -0 "$second" 2>/dev/null; then kill "$second"; wait "$second" 2>/dev/null; fail "a second server on port $port started"
else wait "$second"; rc=$?; [ $rc -eq 2 ] && grep -q 'cannot listen' "$tmp/second.err" && pass "second server on the same port: exit 2" || fail "second server: rc=$rc $(cat "$tmp/second.err")"; fi

# --- size options: a sign, a fraction or a value over 2^64 - 1 is a usage error (exit 2), never "no limit" ----------
size_flag() {  # size_flag NAME VALUE COMMAND...
  local name="$1" value="$2"; shift 2
  timeout 10 "$@" "$name" "$value" > "$tmp/size.out" 2> "$tmp/size.err"; local rc=$?
  if [ $rc -eq 2 ] && grep -q -- "$name: '$value' is not a size" "$tmp/size.err"; then pass "$name $value: exit 2, '$(head -1 "$tmp/size.err" | cut -c1-60)...'"
  else fail "$name $value: rc=$rc $(head -c 200 "$tmp/size.err")"; fi
}
for v in -1 18446744073709551616 16EB 1.5MB +5 5XB; do
  size_flag --max-size "$v" "$essi" check "$tape"
  for flag in --max-body --max-store --min-transfer-rate; do size_flag "$flag" "$v" "$essi" serve --port 0 --web-root "$tmp/web" --data "$tmp/data3"; done
done
"$essi" check --max-size 18446744073709551615 "$tape" > /dev/null 2>&1 && "$essi" check --max-size '15 EB' "$tape" > /dev/null 2>&1 && \
  "$essi" check --max-size 1kib "$tape" > /dev/null 2>&1 && pass "--max-size 2^64-1, '15 EB' and 1kib are sizes" || fail "valid sizes refused"
finish
