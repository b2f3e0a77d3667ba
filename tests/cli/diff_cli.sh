#!/usr/bin/env bash
# `essi diff A B` as a user runs it (docs/cli.md): exit 0 when the revisions cut the same, 1 when they differ, 2 for
# a file that cannot be read; every example tape against its own conversion to absolute coordinates and to EIA
# (every line different, the same contours); a part moved, in text and JSON. Usage: diff_cli.sh PATH/TO/essi
set -uo pipefail
essi="${1:?usage: diff_cli.sh ESSI}"
root="$(cd "$(dirname "$0")/../.." && pwd)"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
failures=0
pass() { echo "ok   - $1"; }
fail() { echo "FAIL - $1"; failures=$((failures + 1)); }

# 1. Each example and real tape (../shared/corpus, when there) without errors against its conversions: the same
# contours (exit 0, "0 moved ...").
tapes=("$root"/examples/*.esi)
[ -d "$root/../shared/corpus/essiconv" ] && tapes+=("$root"/../shared/corpus/essiconv/*.esi)
for f in "${tapes[@]}"; do
  name="$(basename "$f")"
  "$essi" check --profile auto "$f" >/dev/null 2>&1 || continue  # (tapes with errors: their cut is not defined)
  # (a parabola is written as arcs within the chord tolerance, W502: another shape, rightly "changed")
  "$essi" trace --profile auto "$f" 2>/dev/null | grep -q " parabola " && continue
  targets=("essi --absolute" "eia")
  grep -Eq "^2[+-]" "$f" && targets=("essi --absolute")  # (EIA has no head addresses: head 2 is left out, W501)
  for target in "${targets[@]}"; do
    "$essi" convert --profile auto --to $target -o "$tmp/conv" "$f" >/dev/null 2>&1 || { fail "$name: convert --to $target"; continue; }
    out="$("$essi" diff --profile auto "$f" "$tmp/conv" 2>&1)"; rc=$?
    if [ $rc -eq 0 ] && grep -q "0 moved, 0 changed, 0 removed, 0 added" <<<"$out"; then pass "$name = its --to $target"
    else fail "$name vs its --to $target: rc $rc: $out"; fi
  done
done

# 2. A part moved 5 mm (the second contour), the lines renumbered by a comment: exit 1, the move with its lines.
printf '7\n+1000+0\n+0+1000\n-1000+0\n+0-1000\n8\n5\n+2000+0\n6\n7\n+500+0\n+0+500\n-500+0\n+0-500\n8\n64\n' > "$tmp/a.esi"
printf '3\nREV B\n4\n7\n+1000+0\n+0+1000\n-1000+0\n+0-1000\n8\n5\n+2050+0\n6\n7\n+500+0\n+0+500\n-500+0\n+0-500\n8\n64\n' > "$tmp/b.esi"
out="$("$essi" diff "$tmp/a.esi" "$tmp/b.esi")"; rc=$?
if [ $rc -eq 1 ] && grep -q "^moved: A lines 11-14 -> B lines 14-17, by (+5.000, +0.000) mm: cut 200.000 mm from (200.000, 0.000)$" <<<"$out" \
   && grep -q "^contours: 1 same, 1 moved, 0 changed, 0 removed, 0 added$" <<<"$out"; then pass "a moved part (text)"
else fail "a moved part: rc $rc: $out"; fi
json="$("$essi" diff --format json "$tmp/a.esi" "$tmp/b.esi")"
if python3 -c 'import json,sys; j=json.loads(sys.argv[1]); c=j["contours"][0]; assert j["same"] is False and j["summary"]["moved"]==1 and c["change"]=="moved" and c["offset_mm"]==[5.0,0.0] and c["a"]["first_line"]==11 and c["b"]["first_line"]==14, j' "$json"
then pass "a moved part (json)"; else fail "a moved part (json): $json"; fi

# 3. A file that cannot be read: exit 2 and the reason.
out="$("$essi" diff "$tmp/a.esi" "$tmp/missing.esi" 2>&1)"; rc=$?
if [ $rc -eq 2 ] && grep -q "missing.esi" <<<"$out"; then pass "a missing file: exit 2"; else fail "a missing file: rc $rc: $out"; fi

echo "diff_cli: $failures failure(s)"
[ $failures -eq 0 ]
