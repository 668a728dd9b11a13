#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "app/batch_command.h"

namespace sedem::app {

// index.html in a batch's folder, beside summary.csv: one row per run (a link to its
// report.html, the swept value, the seed, each test's error and bias, wall time, particles,
// status, "partial" where a run did not complete), the summary figures (SVG with the PNG as
// fallback) and links to the summary CSVs. Opens from the folder with no server.
void write_batch_index(const std::vector<BatchRun>& runs, const std::string& sweep_key,
                       const std::filesystem::path& out_dir);

}  // namespace sedem::app
