#pragma once

#include <cstdint>

#include "core/design/schedule_design.h"
#include "core/scene/scene.h"

namespace sedem {

// Where a design meets the run: its schedules as scenes, and the DEM run that confirms it.

// The scene with only `test` enabled, reading at `schedule`'s times and depth, and the run
// ending at its last reading.
Scene scene_for_schedule(const Scene& scene, const std::string& test,
                         const ReadingSchedule& schedule);

// A design's standard and designed schedules read from one DEM run of the scene (the same
// particles, the same seed: both schedules see one realisation of the suspension), scored
// against the truth as the reference's were.
struct ScheduleConfirmation {
  std::int64_t particles = 0;
  double wall_seconds = 0;
  ScheduleScore standard, designed;
};

// Runs the engine with `particles` simulated particles and the design's `size_count` sizes;
// one run when both schedules read at the same depth, two (same seed) when they do not.
ScheduleConfirmation confirm_with_dem(const Scene& scene, const ScheduleDesign& design,
                                      std::int64_t particles, std::int64_t size_count);

}  // namespace sedem
