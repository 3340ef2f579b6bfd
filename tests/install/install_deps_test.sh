#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# scripts/install-deps asks only for what a purpose needs, and a user with neither root nor sudo gets the exact
# command for an administrator (exit 1) instead of "sudo: command not found". Runs the real script with stand-ins
# for id (a user, not root) and dpkg-query (nothing installed) on a PATH without sudo.
# Usage: install_deps_test.sh SOURCE_DIR WORK_DIR
set -euo pipefail
# Every assertion stands on a line of its own: under set -e a failing test on the left of && does not stop a script.
src=$1 work=$2
rm -rf "$work" && mkdir -p "$work/bin" && cd "$work"
for tool in bash grep cat; do ln -s "$(command -v $tool)" "bin/$tool"; done
printf '#!/bin/sh\necho 1000\n' > bin/id
printf '#!/bin/sh\nexit 1\n' > bin/dpkg-query
chmod +x bin/id bin/dpkg-query
for need in run test ci web; do
  rc=0; PATH="$work/bin" bash "$src/scripts/install-deps" "$need" > "$need.out" 2> "$need.err" || rc=$?
  cat "$need.err"
  test "$rc" -eq 1
  grep -q "needs root. Ask an administrator to run:" "$need.err"
  grep -q "^  apt-get install -y --no-install-recommends " "$need.err"
done
for need in run test ci; do grep -q "^  apt-get install -y --no-install-recommends .*libsdl2-dev" "$need.err"; done
# the browser build: emscripten and a browser, none of the desktop's libraries or test tools
grep -q " emscripten" web.err
grep -q " chromium" web.err
if grep -q -e libsdl2-dev -e catch2 -e clang "web.err"; then echo "scripts/web would install the desktop's packages"; exit 1; fi
# by purpose: the window alone needs no test framework, benchmark library, X server or clang
if grep -q -e catch2 -e libbenchmark-dev -e xvfb -e clang "run.err"; then echo "scripts/run would install test tools"; exit 1; fi
grep -q "catch2" test.err
if grep -q " clang" test.err; then echo "the tests would install clang"; exit 1; fi
grep -q " clang" ci.err
rc=0; PATH="$work/bin" bash "$src/scripts/install-deps" everything 2> usage.err || rc=$?
test "$rc" -eq 2
echo "install_deps_test: ok"
