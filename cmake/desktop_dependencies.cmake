# SPDX-License-Identifier: MIT
# The desktop build's dependencies: Debian 12's packages (scripts/install-deps installs them). The browser build
# gives the same target names from web/dependencies.cmake, so that algorithms/ and visualizer/ build unchanged.
find_package(glm CONFIG REQUIRED)
find_package(tomlplusplus CONFIG REQUIRED)
find_package(nlohmann_json CONFIG REQUIRED)
find_package(CLI11 CONFIG REQUIRED)
find_package(tinyobjloader CONFIG REQUIRED)
find_package(PkgConfig REQUIRED)
pkg_check_modules(GMPXX REQUIRED IMPORTED_TARGET gmpxx)
if(HSR_WINDOW)
  find_package(SDL2 CONFIG REQUIRED)
  find_package(OpenGL REQUIRED COMPONENTS OpenGL)
  pkg_check_modules(IMGUI REQUIRED IMPORTED_TARGET imgui)
  find_package(GIF REQUIRED)
  find_package(PNG REQUIRED)  # the command line's 16-bit id images (cli/ids_png.cpp)
endif()
# The window's platform layer (visualizer/platform.h): OpenGL 3.3 core, a loop, threads
set(HSR_PLATFORM_SOURCE ${PROJECT_SOURCE_DIR}/visualizer/platform_desktop.cpp)
# Where the program finds its lessons and assets when run from the build tree (state/lesson.cpp, data_dir)
set(HSR_DATA_DIR ${PROJECT_SOURCE_DIR})
