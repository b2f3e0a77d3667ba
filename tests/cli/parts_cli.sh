#!/usr/bin/env bash
# `essi parts TAPE` as a user runs it (docs/cli.md): text, JSON and CSV of tests/data/parts/rect_round_hole.esi with
# its profile (the numbers of rect_round_hole.expected), `essi check --parts` (the JSON report's parts, groups and
# plates; nothing without it), `essi render --remnant` and the exit codes. Usage: parts_cli.sh PATH/TO/essi
set -uo pipefail
essi="${1:?usage: parts_cli.sh ESSI}"
root="$(cd "$(dirname "$0")/../.." && pwd)"
data="$root/tests/data/parts"
tape="$data/rect_round_hole.esi"
profile="$data/rect_round_hole.profile.json"
failures=0
pass() { echo "ok   - $1"; }
fail() { echo "FAIL - $1"; failures=$((failures + 1)); }

# Text
out="$("$essi" parts --lang en --profile "$profile" "$tape")"; rc=$?
if [ $rc -eq 0 ] && grep -qx "1 part in 1 group" <<<"$out" \
   && grep -qx "group 1: 1 x, net area 4685.841 mm², outline 100.000 x 50.000 mm, cut length 362.832 mm a part, holes 1, pierces 2, mass 0.368 kg" <<<"$out" \
   && grep -qx "  part 1 (plate 1): lines 15-18 8-9" <<<"$out" \
   && grep -qx "plate 1: 300.000 x 100.000 mm (profile plate_mm), 1 part, utilisation 15.6 %, scrap 1.987 kg, remnant x 102.000 .. 300.000, y 0.000 .. 100.000 mm" <<<"$out"
then pass "text"; else fail "text: rc $rc: $out"; fi
out="$("$essi" parts --lang de --profile "$profile" "$tape")"
if grep -qx "1 Teil in 1 Gruppe" <<<"$out"; then pass "text in German"; else fail "text in German: $out"; fi

# JSON
json="$("$essi" parts --format json --profile "$profile" "$tape")"; rc=$?
if [ $rc -eq 0 ] && python3 - "$json" <<'PY'
import json, sys
j = json.loads(sys.argv[1])
g = j["groups"][0]
assert j["profile"] == "plate-test", j["profile"]
assert len(j["parts"]) == 1 and len(j["groups"]) == 1 and len(j["plates"]) == 1
assert g["count"] == 1 and abs(g["net_area_mm2"] - 4685.840735) < 1e-6, g
assert g["outline_mm"] == {"length": 100.0, "width": 50.0}, g
assert g["holes"] == 1 and g["pierces"] == 2 and g["mirror_of"] is None and abs(g["mass_kg"] - 0.367838) < 1e-6
assert j["parts"][0]["cuts"] == [{"first_line": 15, "last_line": 18}, {"first_line": 8, "last_line": 9}]
p = j["plates"][0]
assert p["remnant_mm"] == {"x0": 102.0, "y0": 0.0, "x1": 300.0, "y1": 100.0}, p
assert abs(p["utilisation"] - 0.156195) < 1e-6 and abs(p["scrap_kg"] - 1.987162) < 1e-6 and p["from_profile"]
PY
then pass "json"; else fail "json: rc $rc: $json"; fi

# CSV
csv="$("$essi" parts --format csv --profile "$profile" "$tape")"; rc=$?
expected=$'group,count,net_area_mm2,length_mm,width_mm,cut_length_mm,holes,pierces,mass_kg,mirror_of,parts\r\n1,1,4685.841,100.000,50.000,362.832,1,2,0.368,,15-18 8-9\r'
if [ $rc -eq 0 ] && [ "$csv" = "$expected" ]; then pass "csv"; else fail "csv: rc $rc: $(printf %q "$csv")"; fi

# The turned and mirrored copies: groups and twins
out="$("$essi" parts --format csv "$data/mirrored.esi")"
if grep -q "^1,1,2321.460,80.000,50.000,.*,1,2,,2," <<<"$out" && grep -q "^2,2,2321.46[0-9],80.000,50.000,.*,1,2,,1," <<<"$out"
then pass "mirrored twins"; else fail "mirrored twins: $out"; fi

# essi check --parts: the JSON report gets parts, groups and plates; without --parts it has none
json="$("$essi" check --format json --parts --profile "$profile" "$tape" 2>/dev/null)"
plain="$("$essi" check --format json --profile "$profile" "$tape" 2>/dev/null)"
if python3 - "$json" "$plain" <<'PY'
import json, sys
a, b = json.loads(sys.argv[1])["files"][0], json.loads(sys.argv[2])["files"][0]
assert a["groups"][0]["count"] == 1 and a["plates"][0]["remnant_mm"]["x0"] == 102.0
assert "parts" not in b and "groups" not in b and "plates" not in b
for k in b: assert a[k] == b[k], k
PY
then pass "check --parts"; else fail "check --parts"; fi

# essi render --remnant: the plate and its remnant drawn
svg="$("$essi" render --remnant --profile "$profile" -o - "$tape" 2>/dev/null)"
if grep -q '<rect class="remnant" data-plate="1" data-remnant-mm="102 0 300 100"' <<<"$svg" && grep -q '<rect class="plate" data-plate="1"' <<<"$svg"
then pass "render --remnant"; else fail "render --remnant"; fi

# A file that cannot be read: exit 2
"$essi" parts "$data/no such tape.esi" >/dev/null 2>&1; rc=$?
if [ $rc -eq 2 ]; then pass "unreadable: exit 2"; else fail "unreadable: rc $rc"; fi

[ $failures -eq 0 ] && echo "all passed" || echo "$failures failed"
exit $((failures > 0))
