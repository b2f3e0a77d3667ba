# Shared by the tests/serve/*.sh tests: a temporary folder, a stand-in viewer, starting and stopping `essi serve`
# on a free loopback port, and expect/pass/fail helpers. Source it after setting `essi`.
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
tmp="$(mktemp -d)"
server_pid=""
url=""
failures=0
stop_server() { if [ -n "$server_pid" ]; then kill "$server_pid" 2>/dev/null; wait "$server_pid" 2>/dev/null; fi; server_pid=""; }
cleanup() { stop_server; rm -rf "$tmp"; }
trap cleanup EXIT
pass() { echo "ok   - $1"; }
fail() { echo "FAIL - $1"; failures=$((failures + 1)); }
finish() { echo "# $failures failure(s)"; [ "$failures" -eq 0 ]; }

# A stand-in viewer with an inline script, an inline style and an event handler attribute (like web/index.html),
# plus build-tree files that must never be served.
make_web_root() {
  mkdir -p "$tmp/web/CMakeFiles" "$tmp/examples"
  printf '<!doctype html><title>stand-in viewer</title>\n<style>body{margin:0}</style>\n<canvas oncontextmenu="event.preventDefault()"></canvas>\n<script>\nconsole.log(1);\n</script>\n<script src="essi_viewer.js"></script>\n' > "$tmp/web/index.html"
  echo 'not really wasm' > "$tmp/web/essi_viewer.wasm"
  echo 'console.log("viewer")' > "$tmp/web/essi_viewer.js"
  echo "set(SOURCE_DIR $root)" > "$tmp/web/cmake_install.cmake"
  echo 'SECRET-BUILD-TREE' > "$tmp/web/CMakeFiles/secret.txt"
  cp "$root/examples/absolute_offset.esi" "$tmp/examples/"
}

# start_server LOG ARGS...: starts essi serve on a free port; sets server_pid and url (empty when it did not start).
start_server() {
  local log="$1"; shift
  "$essi" serve --host 127.0.0.1 --port 0 --web-root "$tmp/web" --examples "$tmp/examples" "$@" > "$tmp/$log.out" 2> "$tmp/$log.err" &
  server_pid=$!
  url=""
  for _ in $(seq 1 200); do
    url="$(grep -o 'http://127\.0\.0\.1:[0-9]*' "$tmp/$log.out" 2>/dev/null | head -1)"
    [ -n "$url" ] && return 0
    kill -0 "$server_pid" 2>/dev/null || break
    sleep 0.05
  done
  echo "FAIL - server did not start"; cat "$tmp/$log.out" "$tmp/$log.err"; exit 1
}

# expect NAME STATUS_WANTED BODY_REGEX -- curl args...   (headers of the response in $tmp/headers)
expect() {
  local name="$1" want="$2" regex="$3"; shift 3; [ "$1" = "--" ] && shift
  local code body
  code="$(curl -sS -o "$tmp/body" -D "$tmp/headers" -w '%{http_code}' -H 'Expect:' "$@")" || { fail "$name: curl failed"; return; }
  body="$(cat "$tmp/body")"
  if [ "$code" != "$want" ]; then fail "$name: HTTP $code, expected $want (body: ${body:0:300})"; return; fi
  if ! grep -Eq -- "$regex" <<<"$body"; then fail "$name: body does not match /$regex/: ${body:0:300}"; return; fi
  pass "$name ($code)"
}
# header_count NAME: how many times the last response had the header NAME.
header_count() { grep -ic "^$1:" "$tmp/headers"; }
header_value() { grep -i "^$1:" "$tmp/headers" | head -1 | cut -d: -f2- | tr -d '\r' | sed 's/^ //'; }
