#!/usr/bin/env bash
# The language of `essi`'s messages and reports (docs/cli.md, "Languages"): --lang en|de|zh, else LC_ALL,
# LC_MESSAGES, LANG in that order; an unknown --lang is a usage error (exit 2); every format speaks the language
# (text, stats, JSON, SARIF, GitHub, JUnit) while codes, paths and numbers stay the same. Usage: lang_cli.sh ESSI
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
expect "LANG=zh_CN.GB18030" "错误 E101" "${clean_env[@]}" LANG=zh_CN.GB18030 "$essi" check "$tape"
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

out="$("$essi" check --lang fr "$tape" 2>&1)"; rc=$?
if [ $rc -eq 2 ] && grep -qF "expected en, de or zh" <<<"$out"; then pass "--lang fr: exit 2 and says why"
else fail "--lang fr: rc $rc: $out"; fi

[ "$failures" -eq 0 ] && echo "all passed" || { echo "$failures failed"; exit 1; }
