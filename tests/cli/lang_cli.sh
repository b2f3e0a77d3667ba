#!/usr/bin/env bash
# The language of `essi`'s messages and reports (docs/cli.md, "Languages"): --lang en|de|zh, else LC_ALL,
# LC_MESSAGES, LANG in that order; an unknown --lang is a usage error (exit 2); every format speaks the language
# (text, stats, JSON, SARIF, GitHub, JUnit), and so do `essi diff`, a bad profile's errors (E402) and N403's
# evidence, while codes, paths and numbers stay the same. Usage: lang_cli.sh ESSI
set -uo pipefail
essi="${1:?usage: lang_cli.sh ESSI}"
root="$(cd "$(dirname "$0")/../.." && pwd)"
tape="$root/examples/bad_character.esi"
failures=0
pass() { echo "ok   - $1"; }
fail() { echo "FAIL - $1"; failures=$((failures + 1)); }
# expect NAME PATTERN COMMAND...: the command's stdout+stderr holds PATTERN (a fixed string)
expect() {
  local name="$1" pattern="$2"; shift 2
  local out; out="$("$@" 2>&1)"
  if grep -qF -- "$pattern" <<<"$out"; then pass "$name"; else fail "$name: expected '$pattern' in: $out"; fi
}
clean_env=(env -u LC_ALL -u LC_MESSAGES -u LANG)

expect "--lang en" "error E101: unexpected" "${clean_env[@]}" "$essi" check --lang en "$tape"
expect "--lang de" "Fehler E101: unerwartetes Zeichen" "${clean_env[@]}" "$essi" check --lang de "$tape"
expect "--lang zh" "错误 E101: 意外的字符" "${clean_env[@]}" "$essi" check --lang zh "$tape"
expect "--lang de summary" "1 Datei geprüft (Profil iso6582)" "${clean_env[@]}" "$essi" check --lang de "$tape"
expect "no language set: English" "1 file checked" "${clean_env[@]}" "$essi" check "$tape"
expect "LANG=de_DE.UTF-8" "Fehler E101" "${clean_env[@]}" LANG=de_DE.UTF-8 "$essi" check "$tape"
# A GB 18030 locale: Chinese, written in GB 18030 for its terminal (text reports and stderr); JSON stays UTF-8.
from_gb18030() { "$@" 2>&1 | iconv -f GB18030 -t UTF-8; }
expect "LANG=zh_CN.GB18030" "错误 E101" from_gb18030 "${clean_env[@]}" LANG=zh_CN.GB18030 "$essi" check "$tape"
expect "LANG=zh_CN.GB18030: the summary on stderr" "已检查 1 个文件" from_gb18030 "${clean_env[@]}" LANG=zh_CN.GB18030 "$essi" check "$tape"
expect "LANG=zh_CN.GB18030: JSON in UTF-8" '"message": "意外的字符' "${clean_env[@]}" LANG=zh_CN.GB18030 "$essi" check --format json "$tape"
expect "LANG=fr_FR.UTF-8: English" "error E101" "${clean_env[@]}" LANG=fr_FR.UTF-8 "$essi" check "$tape"
expect "LC_MESSAGES before LANG" "错误 E101" "${clean_env[@]}" LANG=de_DE.UTF-8 LC_MESSAGES=zh_CN.UTF-8 "$essi" check "$tape"
expect "LC_ALL before both" "error E101" "${clean_env[@]}" LANG=de_DE.UTF-8 LC_MESSAGES=zh_CN.UTF-8 LC_ALL=C "$essi" check "$tape"
expect "--lang before LANG" "error E101" "${clean_env[@]}" LANG=de_DE.UTF-8 "$essi" check --lang en "$tape"
expect "stats --lang de" "Schnittlänge:" "${clean_env[@]}" "$essi" stats --lang de "$root/examples/plate_holes.esi"
expect "stats --lang zh" "切割长度:" "${clean_env[@]}" "$essi" stats --lang zh "$root/examples/plate_holes.esi"
expect "json --lang de" '"message": "unerwartetes Zeichen' "${clean_env[@]}" "$essi" check --format json --lang de "$tape"
expect "json keeps codes" '"code": "E101"' "${clean_env[@]}" "$essi" check --format json --lang zh "$tape"
expect "sarif --lang zh" '"text": "意外的字符' "${clean_env[@]}" "$essi" check --format sarif --lang zh "$tape"
expect "sarif rules --lang de" 'Ein Satz enthält außerhalb eines 3/4-Ausblendbereichs' "${clean_env[@]}" "$essi" check --format sarif --lang de "$tape"
expect "github --lang de" "::unerwartetes Zeichen" "${clean_env[@]}" "$essi" check --format github --lang de "$tape"
expect "junit --lang zh" "1 个错误" "${clean_env[@]}" "$essi" check --format junit --lang zh "$tape"

# essi diff: two revisions of plate_holes.esi, the second hole moved 5 mm (its rapid there 5 mm longer, the one back
# 5 mm shorter): the difference and the counts in the language asked for, the JSON's keys and values as they are.
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
sed -e 's/^+1300+0$/+1350+0/' -e 's/^-2650+0$/-2700+0/' "$root/examples/plate_holes.esi" > "$tmp/b.esi"
plate="$root/examples/plate_holes.esi"
expect "diff --lang en" "moved: A lines 24-25 -> B lines 24-25, by (+5.000, +0.000) mm: cut 145.664 mm from (245.000, 120.000)" \
  "${clean_env[@]}" "$essi" diff --lang en "$plate" "$tmp/b.esi"
expect "diff --lang de" "verschoben: A Zeilen 24-25 -> B Zeilen 24-25, um (+5.000, +0.000) mm: Schnitt 145.664 mm ab (245.000, 120.000)" \
  "${clean_env[@]}" "$essi" diff --lang de "$plate" "$tmp/b.esi"
expect "diff --lang de counts" "Konturen: 2 gleich, 1 verschoben, 0 geändert, 0 entfernt, 0 hinzugefügt" \
  "${clean_env[@]}" "$essi" diff --lang de "$plate" "$tmp/b.esi"
expect "diff --lang zh" "移位:A 第 24-25 行 -> B 第 24-25 行" "${clean_env[@]}" "$essi" diff --lang zh "$plate" "$tmp/b.esi"
expect "diff json --lang de keeps keys" '"change": "moved"' "${clean_env[@]}" "$essi" diff --format json --lang de "$plate" "$tmp/b.esi"

# A profile that cannot be used (E402) in the language asked for, then exit 2.
printf '{"feed_mm_min": "fast", "colour": 1}\n' > "$tmp/bad.json"
expect "bad profile --lang zh" '错误 E402: "feed_mm_min" 必须是数值' "${clean_env[@]}" "$essi" check --lang zh --profile "$tmp/bad.json" "$plate"
expect "bad profile --lang zh, unknown key" '错误 E402: 未知的键 "colour"' "${clean_env[@]}" "$essi" check --lang zh --profile "$tmp/bad.json" "$plate"
expect "bad profile --lang de" 'Fehler E402: "feed_mm_min" muss eine Zahl sein' "${clean_env[@]}" "$essi" check --lang de --profile "$tmp/bad.json" "$plate"
"$essi" check --lang zh --profile "$tmp/bad.json" "$plate" >/dev/null 2>&1; rc=$?
if [ $rc -eq 2 ]; then pass "bad profile: exit 2"; else fail "bad profile: rc $rc"; fi

# N403's evidence in the reader's language.
expect "N403 --lang de" 'woyda: `135+2` setzt die Anzahl Brenner in Zeile 9' \
  "${clean_env[@]}" "$essi" check --lang de --profile iso6582 "$root/examples/woyda_end_slash.esi"

out="$("$essi" check --lang fr "$tape" 2>&1)"; rc=$?
if [ $rc -eq 2 ] && grep -qF "expected en, de or zh" <<<"$out"; then pass "--lang fr: exit 2 and says why"
else fail "--lang fr: rc $rc: $out"; fi

[ "$failures" -eq 0 ] && echo "all passed" || { echo "$failures failed"; exit 1; }
