# SPDX-License-Identifier: MIT
# The page: hsrviz.html, .js, .wasm and .data (the lessons, scenes, string catalogues and the DejaVu fonts, packed at
# the paths the window reads them from), in the build folder's site/.
add_executable(hsrviz ${PROJECT_SOURCE_DIR}/web/main_web.cpp)
target_link_libraries(hsrviz PRIVATE hsr_window hsr_state hsr_analysis hsr_warnings)
set(fonts /usr/share/fonts/truetype/dejavu)
target_link_options(hsrviz PRIVATE
  -sALLOW_MEMORY_GROWTH=1 -sMINIFY_HTML=0  # (Debian 12 emscripten's minifier call is broken)
  -lidbfs.js -sEXPORTED_RUNTIME_METHODS=ccall  # the settings in IndexedDB; the page's script calls the window
  # long work's progress frames reach the screen and Esc reaches the work (platform.h let_the_frame_show); the
  # saved stack of a pause holds a deep machine's frames
  -sASYNCIFY -sASYNCIFY_STACK_SIZE=1048576
  "SHELL:--shell-file ${PROJECT_SOURCE_DIR}/web/shell.html"
  "SHELL:--preload-file ${PROJECT_SOURCE_DIR}/lessons@/hsrviz/lessons"
  "SHELL:--preload-file ${PROJECT_SOURCE_DIR}/assets@/hsrviz/assets"
  "SHELL:--preload-file ${fonts}/DejaVuSans.ttf@${fonts}/DejaVuSans.ttf"
  "SHELL:--preload-file ${fonts}/DejaVuSansMono.ttf@${fonts}/DejaVuSansMono.ttf")
set_target_properties(hsrviz PROPERTIES SUFFIX ".html" RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/site
                      LINK_DEPENDS ${PROJECT_SOURCE_DIR}/web/shell.html)
# EM_ASM's JavaScript names its arguments $0, $1, …: not an identifier of ours (this folder compiles both files)
set_source_files_properties(${PROJECT_SOURCE_DIR}/web/platform_web.cpp ${PROJECT_SOURCE_DIR}/web/main_web.cpp
                            PROPERTIES COMPILE_OPTIONS -Wno-dollar-in-identifier-extension)
