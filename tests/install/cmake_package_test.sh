#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The algorithms as a CMake package: installed on request (the development component, not in a plain install or the
# .deb), then a course's own project (tests/install/consumer) finds it with find_package(hsrviz), builds and runs.
# Usage: cmake_package_test.sh BUILD_DIR SOURCE_DIR WORK_DIR CXX_COMPILER SANITIZE(ON/OFF)
set -euo pipefail
build=$1 src=$2 work=$3 cxx=$4 sanitize=$5
rm -rf "$work" && mkdir -p "$work" && cd "$work"
flags=""
if [ "$sanitize" = ON ]; then flags="-fsanitize=address,undefined"; fi  # the library was built with them

cmake --install "$build" --prefix "$work/prefix" --component development > install.log
test -f prefix/lib/cmake/hsrviz/hsrvizConfig.cmake
test -f prefix/lib/cmake/hsrviz/hsrvizConfigVersion.cmake
test -f prefix/include/hsrviz/clipping/cohen_sutherland.h
test -f prefix/include/hsrviz/core/steps.h
find prefix -name libhsr_algorithms.a | grep -q .

cmake -S "$src/tests/install/consumer" -B consumer -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_CXX_COMPILER="$cxx" \
      -DCMAKE_CXX_FLAGS="$flags" > configure.log
cmake --build consumer > build.log
consumer/course_exercise | tee run.txt
grep -q "visible part ends at x = 1, y = 0.166667: right" run.txt
grep -qi "outcode" run.txt  # the machine's own sentences

# a version the package is not: refused
sed 's/find_package(hsrviz 0.9/find_package(hsrviz 7.0/' "$src/tests/install/consumer/CMakeLists.txt" > CMakeLists.txt
cp "$src/tests/install/consumer/course_exercise.cpp" .
if cmake -S . -B wrong-version -DCMAKE_PREFIX_PATH="$work/prefix" > wrong.log 2>&1; then
  echo "find_package(hsrviz 7.0) found version 0.9"; exit 1
fi
echo "the CMake package works"
