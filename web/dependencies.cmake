# SPDX-License-Identifier: MIT
# The browser build's dependencies, from what scripts/web gathered in HSR_WEB_DEPS: Debian's source packages of
# SDL2, GMP and giflib compiled with emscripten, Dear ImGui's sources, and the headers of Debian's header-only
# libraries (GLM, toml++, JSON, CLI11, stb, tinyobjloader). Each under the target name the desktop's find_package
# gives it (cmake/desktop_dependencies.cmake), so that algorithms/ and visualizer/ build unchanged.
if(NOT HSR_WEB_DEPS)
  message(FATAL_ERROR "the browser build needs -DHSR_WEB_DEPS=… (bash scripts/web gathers them)")
endif()
set(deps ${HSR_WEB_DEPS})

# What Debian 12's emscripten 3.1.6 lacks of C++20 (<coroutine>, std::bit_cast), before every source
include_directories(BEFORE ${PROJECT_SOURCE_DIR}/web/compat)
add_compile_options(-include ${PROJECT_SOURCE_DIR}/web/compat/web_compat.h)
# emscripten 3.1.6's libc++ has C++20 coroutines only as <experimental/coroutine> (web/compat/coroutine), which
# clang 14 warns will go in LLVM 15: true, and not ours to change here
add_compile_options(-Wno-deprecated-experimental-coroutine)
# Errors are C++ exceptions (a bad lesson file is said, not a crash): emscripten's default only aborts on a throw
add_compile_options(-fexceptions)
add_link_options(-fexceptions)

function(hsr_header_only name)
  add_library(${name} INTERFACE IMPORTED GLOBAL)
  set_target_properties(${name} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES ${deps}/include)
endfunction()
hsr_header_only(glm::glm)
hsr_header_only(tomlplusplus::tomlplusplus)
hsr_header_only(nlohmann_json::nlohmann_json)
hsr_header_only(CLI11::CLI11)

# the implementations Debian's libstb and libtinyobjloader hold on the desktop
add_library(hsr_web_third_party STATIC ${PROJECT_SOURCE_DIR}/web/third_party.cpp)
target_include_directories(hsr_web_third_party SYSTEM PUBLIC ${deps}/include)
target_compile_definitions(hsr_web_third_party PUBLIC TINYOBJLOADER_USE_DOUBLE)
add_library(tinyobjloader::tinyobjloader_double INTERFACE IMPORTED GLOBAL)  # imported: the algorithms' export names it
set_target_properties(tinyobjloader::tinyobjloader_double PROPERTIES INTERFACE_LINK_LIBRARIES hsr_web_third_party)

add_library(PkgConfig::GMPXX INTERFACE IMPORTED GLOBAL)
set_target_properties(PkgConfig::GMPXX PROPERTIES INTERFACE_INCLUDE_DIRECTORIES ${deps}/include
                      INTERFACE_LINK_LIBRARIES "${deps}/lib/libgmpxx.a;${deps}/lib/libgmp.a")

if(HSR_WINDOW)
  # SDL2's headers before emscripten's own SDL 1 compatibility headers: not a system directory (searched first)
  add_library(SDL2::SDL2 STATIC IMPORTED GLOBAL)
  set_target_properties(SDL2::SDL2 PROPERTIES IMPORTED_LOCATION ${deps}/lib/libSDL2.a
                        INTERFACE_INCLUDE_DIRECTORIES ${deps}/include/SDL2 IMPORTED_NO_SYSTEM ON)
  add_library(OpenGL::OpenGL INTERFACE IMPORTED GLOBAL)  # WebGL 2 is OpenGL ES 3.0
  set_target_properties(OpenGL::OpenGL PROPERTIES INTERFACE_LINK_OPTIONS "-sMIN_WEBGL_VERSION=2;-sMAX_WEBGL_VERSION=2")
  add_library(GIF::GIF STATIC IMPORTED GLOBAL)
  set_target_properties(GIF::GIF PROPERTIES IMPORTED_LOCATION ${deps}/lib/libgif.a INTERFACE_INCLUDE_DIRECTORIES ${deps}/include)
  # Dear ImGui 1.86 (Debian's source package): its core and the SDL2 and OpenGL 3 backends, as libimgui.a has them
  set(IMGUI_INCLUDEDIR ${deps}/imgui)
  add_library(hsr_web_imgui STATIC ${deps}/imgui/imgui.cpp ${deps}/imgui/imgui_draw.cpp ${deps}/imgui/imgui_tables.cpp
              ${deps}/imgui/imgui_widgets.cpp ${deps}/imgui/backends/imgui_impl_sdl.cpp ${deps}/imgui/backends/imgui_impl_opengl3.cpp)
  target_include_directories(hsr_web_imgui SYSTEM PUBLIC ${deps}/imgui)
  # its OpenGL backend told the GL state the window leaves, instead of asking WebGL (web/compat/imgui_gl_state.h)
  target_sources(hsr_web_imgui PRIVATE ${PROJECT_SOURCE_DIR}/web/imgui_gl_state.cpp)
  set_source_files_properties(${deps}/imgui/backends/imgui_impl_opengl3.cpp PROPERTIES
                              COMPILE_OPTIONS "-include;${PROJECT_SOURCE_DIR}/web/compat/imgui_gl_state.h")
  target_link_libraries(hsr_web_imgui PUBLIC SDL2::SDL2 OpenGL::OpenGL)
  add_library(PkgConfig::IMGUI ALIAS hsr_web_imgui)
endif()

set(HSR_PLATFORM_SOURCE ${PROJECT_SOURCE_DIR}/web/platform_web.cpp)
set(HSR_DATA_DIR /hsrviz)  # where the page's packed files are (web/page.cmake)
