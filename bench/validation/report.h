#pragma once

#include <string>
#include <vector>

#include "bench/validation/checks.h"
#include "bench/validation/run_folder.h"

namespace sedem::validation {

// The run folders behind docs/validation.md.
struct ReportInputs {
  std::vector<RunFolder> runs;       // the five samples, full count
  std::vector<RunFolder> reduced;    // the same scenes with fewer particles
  std::vector<RunFolder> weighting;  // the reduced runs with another weighting scheme
  std::vector<RunFolder> depth;      // the runs' particles read again at other depths
  double early_s = 3600;             // "the early part of the test": readings up to this
  std::string machine;               // where the runs were made, for the cost table
};

// A generated part of docs/validation.md (between its markers) and one line per verdict.
struct Section {
  std::string name, markdown;
};
struct Check {
  std::string id, claim;
  Verdict verdict = Verdict::inconclusive;
  std::string evidence;  // the numbers behind the verdict, one line
  std::string where;     // the figure or table of docs/validation.md that shows it
};
struct Report {
  std::vector<Section> sections;
  std::vector<Check> checks;
};

Report build_report(const ReportInputs& in);

// "smoothing: supports -- hydrometer ..." for the console.
std::string verdict_line(const Check& check);

// The paper's compute times (Sect. 5.2): 60 h for sample 2 and 420 h for sample 3 on a 12-core
// Core i7-4930K, for 40 000 s of sedimentation (Fig. 18). 0 for the other samples.
double paper_hours(const std::string& sample);
inline constexpr double kPaperSimulatedSeconds = 40000;

}  // namespace sedem::validation
