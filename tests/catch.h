// SPDX-License-Identifier: MIT
// The one include of Catch2: a move to v3 changes this line only.
#pragma once
#include <catch2/catch.hpp>
