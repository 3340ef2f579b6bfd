#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Every source file, build file and script of the project names its licence in its first lines
# (SPDX-License-Identifier: MIT), so that a file copied out of the project still says under what terms.
#   spdx_test.sh SOURCE_DIR
set -euo pipefail
cd "$1"
missing=0
while IFS= read -r -d '' file; do
  if ! head -n 2 "$file" | grep -q "SPDX-License-Identifier: MIT"; then
    echo "no SPDX licence line in the first two lines of $file"
    missing=$((missing + 1))
  fi
done < <(find algorithms visualizer tests scripts .ci web cmake CMakeLists.txt \
           \( -name '*.cpp' -o -name '*.h' -o -name '*.sh' -o -name '*.py' -o -name 'CMakeLists.txt' -o -name '*.cmake' \
              -o -name '*.html' -o -path 'scripts/*' -o -path '.ci/*' -o -path 'web/compat/*' \) \
           -type f -not -path '*/corpus/*' -print0)
test "$missing" -eq 0
echo "every source, build file and script names its licence"
