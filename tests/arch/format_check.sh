#!/bin/bash
# Every C++ file of the project (git ls-files, third_party/ aside) is as clang-format 14 writes it with the root's
# .clang-format. Prints the files that are not, with the first lines that differ; exits 1 if there is any.
# Usage: format_check.sh ROOT        (reformat: clang-format-14 -i FILE...)
set -u
root=${1:?usage: format_check.sh ROOT}
formatter=$(command -v clang-format-14 || true)
if [ -z "$formatter" ]; then
  echo "format_check: clang-format-14 not found (Debian clang-format-14; scripts/setup test installs it)" >&2
  exit 1
fi
cd "$root" || exit 1
bad=0
while IFS= read -r f; do
  if ! out=$("$formatter" --style=file "$f" | diff -u "$f" - ); then
    echo "$f: not formatted (clang-format-14 -i $f):"
    printf '%s\n' "$out" | sed -n '3,12p'
    bad=$((bad + 1))
  fi
done < <(git ls-files -- '*.cpp' '*.hpp' '*.h' '*.cc' | grep -v '^third_party/')
if [ $bad -gt 0 ]; then echo "format_check: $bad file(s) not formatted"; exit 1; fi
echo "format_check: every C++ file formatted"
