#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "bench/validation/study.h"

namespace sedem::validation {

// The study's files: seed batches (`sedem batch --seeds`) read in, and its part of
// docs/validation.md, study.csv and study_seeds.csv written out.

// Every run folder (a folder with run.json) directly inside `batch_dir`, by name; a folder
// that cannot be read is named on stderr and left out, so one failed run does not lose the
// study.
std::vector<RunFolder> read_batch(const std::filesystem::path& batch_dir);

// The runs grouped by their scene's sample.seed, the depth runs beside the main runs of the
// same seed. Seeds without main runs are left out.
std::vector<SeedRuns> group_by_seed(const std::vector<RunFolder>& runs,
                                    const std::vector<RunFolder>& shallow,
                                    const std::vector<RunFolder>& deep);

// A regime's folder as scripts/validate.sh --study writes it: main/ and, when the depth runs
// were made, shallow/ and deep/ (each a seed batch). A folder without main/ is taken as the
// main batch itself.
StudyRegime read_regime(const std::string& label, const std::filesystem::path& dir,
                        double early_s = kStudyEarlyTime);

// The generated section "study" of docs/validation.md: the rule, then a table per regime.
std::string study_markdown(const std::vector<StudyRegime>& regimes);
// study.csv (one row per regime and conclusion) and study_seeds.csv (every seed's effects).
void write_study_files(const std::vector<StudyRegime>& regimes,
                       const std::filesystem::path& out_dir);
// "passing 3: supports (effect 1.20 [0.40, 2.00] pp, 10 seeds)" for the console.
std::string study_line(const StudyRegime& regime, const StudyConclusion& c);

}  // namespace sedem::validation
