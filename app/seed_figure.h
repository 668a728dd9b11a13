#pragma once

#include <filesystem>
#include <vector>

#include "app/batch_summary.h"
#include "render/drawing/figure_files.h"

namespace sedem::app {

// summary_granulometry.png (+ .csv) in out_dir: Fig. 18 over the seeds, one panel per group.
// Each test's DEM curve is the mean over the group's complete runs at each reading time (the
// seeds read at the same times; their diameters differ little, so the mean diameter), with
// the 95 % interval of that mean as a band; the true curve and the reference solution's
// curve (neither depends on the seed) are the first complete run's. Groups with no complete
// run are left out; nothing is written when none has one.
void write_seed_granulometry(const std::vector<SeedGroup>& groups,
                             const render::FigureOutput& figures,
                             const std::filesystem::path& out_dir);

}  // namespace sedem::app
