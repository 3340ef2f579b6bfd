// SPDX-License-Identifier: MIT
// Every algorithm the tool can step through: one line each in registry.cpp. An algorithm's `machine` is a value of
// its family's own type (the clippers' ClipAlgorithm, the ray cast's Acceleration, …), so the one place that turns
// an algorithm into a session (visualizer/state/families.h) visits it instead of switching over numbers.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <variant>

#include "clipping/clip_scene.h"
#include "culling/backface.h"
#include "raycast/raycast_events.h"

namespace hsr::algo {

// The machines of the families that have no enum of their own in their folder.
enum class BspMachine : std::uint8_t { build, traversal };  // the traversal lesson starts with the tree built
enum class ZBufferMachine : std::uint8_t { fill };
enum class ScanLineMachine : std::uint8_t { scan_line, classic };  // classic: no z-buffer, the Brown notes' form
enum class ZMergeMachine : std::uint8_t { merge };
enum class DepthSortMachine : std::uint8_t { newell };
enum class PortalMachine : std::uint8_t { pvs, render, render_bbox };  // render_bbox: bounding-box frusta
enum class CullingMachine : std::uint8_t { bounds, frustum, detail, occluders, hiz };
enum class HorizonMachine : std::uint8_t { floating_horizon };
enum class CompositeMachine : std::uint8_t { alpha };
enum class RobertsMachine : std::uint8_t { hidden_lines };
enum class PerspectiveMachine : std::uint8_t { occluding_pairs };
enum class ABufferMachine : std::uint8_t { resolve };
enum class FormsMachine : std::uint8_t { general_forms };  // object space and image space, side by side
enum class IntersectionMachine : std::uint8_t { hierarchical };  // IntersectionTest(M) over a bounding-volume hierarchy

// One alternative per family.
using Machine = std::variant<ClipAlgorithm, BspMachine, BackfaceTest, ZBufferMachine, Acceleration, ScanLineMachine,
                             ZMergeMachine, DepthSortMachine, PortalMachine, CullingMachine, HorizonMachine, CompositeMachine,
                             RobertsMachine, PerspectiveMachine, ABufferMachine, FormsMachine, IntersectionMachine>;

struct AlgorithmInfo {
    std::string_view id;          // as lessons and the command line name it
    std::string_view title;
    int difficulty;               // 1 (first week) … 5
    Machine machine;
};

std::span<const AlgorithmInfo> algorithms();
std::optional<AlgorithmInfo> find_algorithm(std::string_view id);

}  // namespace hsr::algo
