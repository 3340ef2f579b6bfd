#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# hsrviz installed as software: `cmake --install` into a prefix, and the .deb that cpack makes, unpacked into a
# scratch root with dpkg -x. The installed program finds its lessons beside itself (also when the installation is
# moved), checks every shipped lesson, plays one headless; the .deb depends on runtime libraries only.
# Usage: install_test.sh BUILD_DIR SOURCE_DIR WORK_DIR PNG_CHECK
set -euo pipefail
# Every assertion stands on a line of its own: under set -e a failing test on the left of && does not stop a script.
build=$1 src=$2 work=$3 png_check=$4
rm -rf "$work" && mkdir -p "$work" && cd "$work"
unset HSRVIZ_DATA
export SDL_VIDEODRIVER=offscreen HSRVIZ_CONFIG="$work/window.toml"
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"  # Mesa's llvmpipe at exit, as in the GUI tests

# cmake --install: the usual places
cmake --install "$build" --prefix "$work/prefix" > install.log
test -x prefix/bin/hsrviz
test -f prefix/share/hsrviz/lessons/00_tour.toml
test -f prefix/share/hsrviz/assets/scenes/cs_segments.toml
test -f prefix/share/applications/hsrviz.desktop
test -f prefix/share/icons/hicolor/scalable/apps/hsrviz.svg
test -f prefix/share/doc/hsrviz/LICENSE
# the CMake package (headers, archive) only on request: tests/install/cmake_package_test.sh
if [ -e prefix/include/hsrviz ] || [ -e prefix/lib/cmake/hsrviz ]; then echo "a plain install has the development files"; exit 1; fi
grep -q "^Exec=hsrviz" prefix/share/applications/hsrviz.desktop
grep -q '^\.TH HSRVIZ "1"' prefix/share/man/man1/hsrviz.1
grep -q "render" prefix/share/man/man1/hsrviz.1  # the subcommands, from --help
# ASCII only, the en dash of "Cohen–Sutherland" as groff's \[u2013] (man writes it as "-" in a C locale, not ???)
if LC_ALL=C grep -q '[^ -~	]' prefix/share/man/man1/hsrviz.1; then echo "the man page is not ASCII"; exit 1; fi
grep -qF 'Cohen\[u2013]Sutherland' prefix/share/man/man1/hsrviz.1

# The installation moved elsewhere still finds its own lessons (not the source tree's)
mv prefix moved
moved/bin/hsrviz check > check.txt
cat check.txt | tail -3
grep -q "^ok    $work/moved/share/hsrviz/lessons/00_tour.toml" check.txt
if grep -q -e "$src/lessons" -e "$src/assets" check.txt; then echo "the moved installation read the source tree"; exit 1; fi
moved/bin/hsrviz --lesson-list > list.txt  # into a file: grep -q would close the pipe early, and pipefail fail the writer
grep -q "05_bsp_traversal" list.txt
moved/bin/hsrviz --screenshot shot.png --frames 3 > shot.txt
grep -q "at step" shot.txt
"$png_check" shot.png 1280 800
# data that is not there: a message naming where it looked, exit 1, never an abort
rc=0; HSRVIZ_DATA="$work/nowhere" moved/bin/hsrviz check > nodata.txt 2>&1 || rc=$?
cat nodata.txt
test "$rc" -eq 1
grep -q "nowhere" nodata.txt

# The .deb: runtime dependencies only, and it plays from a scratch root
cpack -G DEB --config "$build/CPackConfig.cmake" -B "$work/deb" > cpack.log
deb=$(ls deb/hsrviz_*.deb)
depends=$(dpkg-deb -f "$deb" Depends)
echo "Depends: $depends"
grep -q "libsdl2-2.0-0" <<< "$depends"
grep -q "fonts-dejavu-core" <<< "$depends"
if grep -q -- "-dev" <<< "$depends"; then echo "a -dev package among the .deb's dependencies"; exit 1; fi
dpkg-deb -f "$deb" Section | grep -q education
dpkg -x "$deb" root
test -f root/usr/share/applications/hsrviz.desktop
root/usr/bin/hsrviz --version | grep -q "^hsrviz [0-9]"
root/usr/bin/hsrviz check > deb-check.txt
grep -q "^ok    $work/root/usr/share/hsrviz/lessons/05_bsp_traversal.toml" deb-check.txt
root/usr/bin/hsrviz "$work/root/usr/share/hsrviz/lessons/04_bsp_build.toml" --screenshot deb.png --frames 3 > deb-shot.txt
"$png_check" deb.png 1280 800
echo "install_test: ok"
