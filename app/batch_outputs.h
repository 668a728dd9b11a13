#pragma once

#include <string>
#include <vector>

#include "app/batch_command.h"

namespace sedem::app {

// The swept key of a batch's options ("sample.seed" of "sample.seed=1,2"), "" without a sweep.
std::string sweep_key(const BatchOptions& options);

// What a batch writes beside its runs, read from their folders in options.out_dir:
// summary.csv, with a sweep the error figure, from two seeds on summary_stats.csv and the
// granulometry over the seeds (printed unless quiet), and index.html. A run with no run.json
// is a row with status "missing". The one writer of a local batch's summary and of
// `sedem batch --gather`'s. Throws on a write that fails.
void write_batch_outputs(const std::vector<BatchRun>& runs, const BatchOptions& options);

}  // namespace sedem::app
