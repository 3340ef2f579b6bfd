# SPDX-License-Identifier: MIT
# find_package(hsrviz CONFIG): the algorithms library, hsrviz::algorithms (C++20), and what its headers and
# archive need from the system (GLM, toml++, tinyobjloader, threads: Debian's packages).
include(CMakeFindDependencyMacro)
find_dependency(glm CONFIG)
find_dependency(tomlplusplus CONFIG)
find_dependency(tinyobjloader CONFIG)
find_dependency(Threads)
include(${CMAKE_CURRENT_LIST_DIR}/hsrviz-targets.cmake)
