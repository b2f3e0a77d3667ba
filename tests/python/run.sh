#!/usr/bin/env bash
# Installs the essikit package with pip from ./python into a fresh virtual environment of Debian's Python (offline:
# --no-index --no-build-isolation; the native module from the CMake build), then runs tests/python with pytest
# (Debian python3-pytest). Usage: run.sh ESSI BUILD_DIR
set -euo pipefail
essi="$(realpath "${1:?usage: run.sh ESSI BUILD_DIR}")"
build="$(realpath "${2:?usage: run.sh ESSI BUILD_DIR}")"
root="$(cd "$(dirname "$0")/../.." && pwd)"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
/usr/bin/python3 -m venv --system-site-packages "$tmp/venv"
# (a copy of ./python: pip builds in the folder it is given)
cp -r "$root/python" "$tmp/src" && cp "$root/CMakeLists.txt" "$tmp/CMakeLists.txt"
ESSIKIT_BUILD="$build" "$tmp/venv/bin/pip" install --quiet --no-index --no-build-isolation "$tmp/src"
cd "$tmp"
ESSI_BIN="$essi" "$tmp/venv/bin/python" -m pytest -q -p no:cacheprovider "$root/tests/python"
