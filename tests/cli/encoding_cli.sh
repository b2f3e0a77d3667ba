#!/usr/bin/env bash
# Tapes saved as UTF-16 with a byte order mark (docs/cli.md, "Text encodings"): `essi check` reads them as text, with
# the findings, lines and columns of the same tape in UTF-8, little-endian and big-endian alike; UTF-16 that is no
# text (an odd number of bytes, an unpaired surrogate) cannot be read, and the message says where.
# Usage: encoding_cli.sh ESSI
set -uo pipefail
essi="$(realpath "${1:?usage: encoding_cli.sh ESSI}")"
root="$(cd "$(dirname "$0")/../.." && pwd)"
failures=0
pass() { echo "ok   - $1"; }
fail() { echo "FAIL - $1"; failures=$((failures + 1)); }
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1

# bad_character.esi: E101 on line 13, column 8 (a letter O typed for a zero), in UTF-8 and in UTF-16 LE and BE.
cp "$root/examples/bad_character.esi" tape.esi
{ printf '\xFF\xFE'; iconv -f UTF-8 -t UTF-16LE tape.esi; } > le.esi
{ printf '\xFE\xFF'; iconv -f UTF-8 -t UTF-16BE tape.esi; } > be.esi
# the report without its summary line (its wall time differs from run to run)
report() { "$essi" check --lang en "$1" 2>&1 | grep -v ' checked (profile '; }
want="$(report tape.esi)"
case "$want" in *"tape.esi:13:8: error E101"*) pass "UTF-8: E101 on line 13, column 8" ;;
                *) fail "UTF-8: expected E101 at 13:8 in: $want" ;; esac
for enc in le be; do
  "$essi" check "$enc.esi" > /dev/null 2>&1
  rc=$?
  got="$(report "$enc.esi")"
  if [ "$rc" -eq 1 ] && [ "${got//$enc.esi/tape.esi}" = "$want" ]; then pass "UTF-16 $enc: the UTF-8 tape's report"
  else fail "UTF-16 $enc (exit $rc): expected the UTF-8 tape's report:
$want
got:
$got"; fi
  a="$("$essi" check --format json tape.esi 2>/dev/null | grep -v '"path"')"
  b="$("$essi" check --format json "$enc.esi" 2>/dev/null | grep -v '"path"')"
  if [ -n "$a" ] && [ "$a" = "$b" ]; then pass "UTF-16 $enc: the same JSON"; else fail "UTF-16 $enc: the JSON differs"; fi
done

# expect NAME EXIT PATTERN FILE: `essi check FILE` exits EXIT and says PATTERN (a fixed string)
expect() {
  local name="$1" code="$2" pattern="$3" file="$4"
  local out rc; out="$("$essi" check --lang en "$file" 2>&1)"; rc=$?
  if [ "$rc" -eq "$code" ] && grep -qF -- "$pattern" <<<"$out"; then pass "$name"
  else fail "$name: expected exit $code and '$pattern', got $rc: $out"; fi
}
{ cat le.esi; printf 'x'; } > odd.esi
bytes=$(wc -c < odd.esi)
expect "an odd number of bytes" 2 \
  "cannot read odd.esi: the file is UTF-16 LE text with an odd number of bytes ($bytes): its last byte, on line 17" odd.esi
# a high surrogate (D800) with no low one after it, at the start of line 2 (byte 2 + 2 x 2 = 6)
printf '\xFF\xFE3\x00\n\x00\x00\xD8A\x00\n\x00' > surrogate.esi
expect "an unpaired surrogate" 2 \
  "the file is UTF-16 LE text with an unpaired surrogate D800 at byte 6 (line 2)" surrogate.esi
printf '\xFE\xFF\x00+\xDC\x00' > low.esi
expect "a low surrogate alone, big-endian" 2 "UTF-16 BE text with an unpaired surrogate DC00 at byte 4 (line 1)" low.esi
out="$("$essi" check --lang de surrogate.esi 2>&1)"
grep -qF "ungepaarten Surrogat D800 bei Byte 6 (Zeile 2)" <<<"$out" && pass "in German" || fail "in German: $out"

echo "$failures failure(s)"
[ "$failures" -eq 0 ]
