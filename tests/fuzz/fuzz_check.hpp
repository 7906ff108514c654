#pragma once
/// What the fuzz harnesses run on a scene: the checks `carom check` and `carom run` make before
/// anything is written, with the limits that keep one fuzz input fast.
#include <functional>

#include "scenarios/scene/scene.hpp"

namespace carom::fuzz {

/// Most particles a fuzzed scene is placed with (build_initial_state, make_method,
/// describe_scene); larger scenes stop after the size checks (planned_particle_count,
/// estimate_output), which is where an oversized input must be refused anyway. Placing
/// thousands of particles is correct but slow, and a fuzzer needs many inputs a second.
constexpr std::size_t kMaxPlacedParticles = 64;

/// Most cells of the neighbour grid a fuzzed scene is placed and started with, estimated as
/// the domain's volume over the smallest diameter cubed. The grid (core/cell_grid.hpp) is sized
/// by the domain and refuses more than 2e8 cells itself; up to that it is correct but takes
/// seconds and hundreds of MB under AddressSanitizer (the shipped settling_sphere.toml, a 16 m
/// column of a 0.5 mm bead, has 1.3e7), which would stall the fuzzer on the seeds.
constexpr double kMaxGridCells = 1e5;

/// Validates `scene` as `carom run` does first (the planned particle count, the output
/// estimate) and as `carom check` does (placement, the method's start checks, the report).
/// Scenes with initial.settle_time (a simulation, not reading) or initial.from_file (the
/// initial-file harness's input) stop after parsing.
void check_like_carom(Scene scene);

/// Runs `body`. A SceneError is the expected answer to bad input; any other exception is a
/// defect (a bad scene must be refused with a message naming file, line and key): it is printed
/// and the process aborts, so that libFuzzer keeps the input.
void expect_scene_errors_only(const std::function<void()>& body);

}  // namespace carom::fuzz
