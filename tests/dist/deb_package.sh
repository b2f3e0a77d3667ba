#!/usr/bin/env bash
# The Debian package of make dist: lintian reports no error; dpkg -i installs essi, its man page, the completions
# and essi-serve.service (accepted by systemd-analyze verify, not enabled, run as the system user essikit with its
# data in /var/lib/essikit); the installed essi checks an example and serves the viewer compiled into it;
# dpkg -r removes every file again.
#   deb_package.sh DEB EXAMPLES_DIR
set -uo pipefail
deb="$1" examples="$2"
failures=0
pass() { echo "ok   - $1"; }
fail() { echo "FAIL - $1"; failures=$((failures + 1)); }
[ -f "$deb" ] || { echo "FAIL - $deb not found (run make dist)"; exit 1; }
[ "$(id -u)" -eq 0 ] || { echo "FAIL - dpkg -i needs root (CI runs as root)"; exit 1; }
for tool in lintian systemd-analyze dpkg-deb; do
  command -v "$tool" >/dev/null || { echo "FAIL - $tool not found (scripts/setup dist installs it)"; exit 1; }
done
case "$(basename "$deb")" in
  essikit_*_amd64.deb) pass "name $(basename "$deb")" ;;
  *) fail "name $(basename "$deb") is not essikit_<version>_amd64.deb" ;;
esac

# lintian: no error (E:) tags.
lint="$(lintian --tag-display-limit 0 "$deb" 2>&1)"
if grep -q "^E:" <<<"$lint"; then fail "lintian errors: $(grep '^E:' <<<"$lint")"; else pass "lintian: no errors"; fi
echo "$lint" | sed 's/^/  lintian: /'

# Depends: only shared libraries (dpkg-shlibdeps), no toolchain or -dev package.
depends="$(dpkg-deb -f "$deb" Depends)"
if [ -n "$depends" ] && ! grep -Eq -- "-dev|emscripten|nodejs|chromium" <<<"$depends"; then pass "Depends: $depends"
else fail "Depends: '$depends'"; fi

dpkg -r essikit >/dev/null 2>&1 || true
if dpkg -i "$deb" >"${TMPDIR:-/tmp}/essikit-dpkg.log" 2>&1; then pass "dpkg -i"; else fail "dpkg -i: $(cat "${TMPDIR:-/tmp}/essikit-dpkg.log")"; fi
for f in /usr/bin/essi /usr/share/man/man1/essi.1.gz /usr/share/bash-completion/completions/essi \
         /usr/share/zsh/vendor-completions/_essi /usr/share/fish/vendor_completions.d/essi.fish \
         /lib/systemd/system/essi-serve.service /usr/share/doc/essikit/copyright /usr/share/essikit/examples/crlf.esi; do
  if [ -e "$f" ]; then pass "installed $f"; else fail "missing $f"; fi
done
if /usr/bin/essi --version | grep -Eq '^essi [0-9.]+ \(commit [0-9a-f]{12}\)$'; then pass "essi --version: $(/usr/bin/essi --version)"
else fail "essi --version: $(/usr/bin/essi --version 2>&1)"; fi
if zcat /usr/share/man/man1/essi.1.gz | grep -q '^\.TH ESSI 1' && man -w essi 2>/dev/null | grep -q essi.1.gz; then
  pass "man essi finds the page"
else
  fail "man page: $(man -w essi 2>&1)"
fi
# essi report's PDF: the writer module is installed where essi looks for it, and loaded only for a PDF.
if [ -f /usr/lib/essikit/essi-pdf.so ]; then pass "installed /usr/lib/essikit/essi-pdf.so"; else fail "missing /usr/lib/essikit/essi-pdf.so"; fi
pdf="$(mktemp --suffix=.pdf)"
if /usr/bin/essi report -o "$pdf" /usr/share/essikit/examples/crlf.esi >/dev/null 2>&1 && head -c 5 "$pdf" | grep -q '%PDF-'; then
  pass "essi report -o job.pdf: a PDF"
else
  fail "essi report -o job.pdf: $(/usr/bin/essi report -o "$pdf" /usr/share/essikit/examples/crlf.esi 2>&1)"
fi
rm -f "$pdf"
if ldd /usr/bin/essi | grep -Eq 'libcairo|libpango'; then fail "essi links cairo or pango: $(ldd /usr/bin/essi | grep -E 'cairo|pango')"
else pass "essi itself links neither cairo nor pango"; fi
out="$(/usr/bin/essi check /usr/share/essikit/examples/bad_arc_off_circle.esi 2>&1)"; rc=$?
if [ $rc -eq 1 ] && grep -q "error" <<<"$out"; then pass "essi check: an example's error, exit 1"; else fail "essi check: rc $rc $out"; fi

verify="$(systemd-analyze verify /lib/systemd/system/essi-serve.service 2>&1)"; rc=$?
if [ $rc -eq 0 ] && ! grep -qi "error\|unknown\|invalid" <<<"$verify"; then pass "systemd-analyze verify essi-serve.service"
else fail "systemd-analyze verify: rc $rc $verify"; fi
if ls /etc/systemd/system/*.wants/essi-serve.service >/dev/null 2>&1; then fail "essi-serve.service is enabled on install"
else pass "essi-serve.service not enabled"; fi
unit=/lib/systemd/system/essi-serve.service
if grep -qx "User=essikit" "$unit" && grep -qx "StateDirectory=essikit" "$unit" && getent passwd essikit | grep -q ":/var/lib/essikit:"; then
  pass "its own system user essikit, data in /var/lib/essikit"
else
  fail "user: $(getent passwd essikit)"
fi

# The unit's command, as the service user: the viewer compiled in and the examples installed.
data="$(mktemp -d)"
chown essikit:essikit "$data" 2>/dev/null
log="$data/serve.log"
setpriv --reuid=essikit --regid=essikit --clear-groups /usr/bin/essi serve --host 127.0.0.1 --port 0 --data "$data/store" >"$log" 2>&1 &
server=$!
url=""
for _ in $(seq 1 100); do url="$(grep -o 'http://127.0.0.1:[0-9]*/' "$log" | head -1)"; [ -n "$url" ] && break; sleep 0.1; done
if [ -n "$url" ] && curl -s "$url" | grep -q essi_viewer.js && curl -s "${url}examples/index.json" | grep -q crlf.esi; then
  pass "essi serve as essikit: the embedded viewer and the installed examples"
else
  fail "essi serve: $(cat "$log")"
fi
kill $server 2>/dev/null
wait $server 2>/dev/null
rm -rf "$data"

files="$(dpkg -L essikit | grep -v '^/\.$')"
if dpkg -r essikit >/dev/null 2>&1; then pass "dpkg -r"; else fail "dpkg -r"; fi
left=""
for f in $files; do [ -f "$f" ] && left="$left $f"; done
status="$(dpkg-query -W -f='${Status}' essikit 2>/dev/null)"
if [ -z "$left" ] && [ "$status" != "install ok installed" ]; then pass "removed cleanly ($status)"; else fail "left after dpkg -r:$left"; fi
dpkg -P essikit >/dev/null 2>&1 || true
[ $failures -eq 0 ]
