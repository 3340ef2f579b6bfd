#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The browser tests: puppeteer-core from npm (into BUILD/node, once; it never downloads a browser: Debian's chromium
# drives the page), the built page served on a free local port, then page_test.js.
# DESKTOP_HSRVIZ is the desktop build's window: one test compares the page with it after the same keys.
#   bash tests/web/run.sh BUILD_DIR DESKTOP_HSRVIZ [--frame-times]    (BUILD_DIR: where scripts/web built the page)
# --frame-times: the benchmark of each lesson's frame times in the page (frame_times.js) instead of the tests.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "$1" && pwd)
desktop=$(realpath "$2")
[ -x "$desktop" ] || { echo "tests/web: no desktop hsrviz at $2 (the comparison needs it)" >&2; exit 1; }
node_dir=$build/node
if [ ! -d "$node_dir/node_modules/puppeteer-core" ]; then
  mkdir -p "$node_dir" && cp "$here/package.json" "$node_dir/"
  (cd "$node_dir" && PUPPETEER_SKIP_DOWNLOAD=1 npm install --no-audit --no-fund --loglevel=error) ||
    { echo "tests/web: npm could not install puppeteer-core from the npm registry (its reason is above)" >&2; exit 1; }
fi
port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
python3 -m http.server "$port" --bind 127.0.0.1 --directory "$build/site" > "$build/server.log" 2>&1 &
server=$!
trap 'kill $server 2>/dev/null || true' EXIT
for _ in $(seq 50); do curl -sf "http://127.0.0.1:$port/hsrviz.html" > /dev/null && break; sleep 0.1; done
mkdir -p "$build/browser-test"
if [ "${3:-}" = --frame-times ]; then  # the benchmark instead: each lesson's frame times in the page
  NODE_PATH=$node_dir/node_modules node "$here/frame_times.js" "http://127.0.0.1:$port/hsrviz.html" "$here/../../lessons"
  exit
fi
NODE_PATH=$node_dir/node_modules node "$here/page_test.js" "http://127.0.0.1:$port/hsrviz.html" "$build/browser-test" \
  "$desktop" "$here/../../lessons"
