#pragma once

#include <string>

namespace sedem::app {

// `sedem batch --gather DIR`: the summary of a batch written by --emit, from its run folders
// once the scheduler's tasks have ended: the same summary.csv, summary_stats.csv, figures and
// index.html as the local batch of the same command (one code writes both). A run whose
// folder holds no run.json is a row with status "missing", one still "running" (or killed)
// keeps that status; each that did not complete is named on stderr. Exit status 0 when every
// run is complete, 5 when one failed, else 2 (a run missing or not finished); 2 also when DIR
// holds no batch plan.
int gather_batch(const std::string& dir, bool quiet);

}  // namespace sedem::app
