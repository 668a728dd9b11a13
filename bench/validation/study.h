#pragma once

#include <array>
#include <string>
#include <vector>

#include "bench/validation/run_folder.h"
#include "core/stats/seed_statistics.h"

namespace sedem::validation {

// The paper's six conclusions decided over seeds instead of from one draw: each becomes one
// number per seed (an effect in pp, positive in the paper's direction), and the 95 % interval
// of its mean over the seeds decides it by a rule fixed before the runs were made, so that
// the verdict cannot be tuned to the result.

// An effect whose whole interval lies within +-this is too small to matter, whichever its
// sign: the resolution of a laboratory reading of percent finer is about 1 pp.
inline constexpr double kPracticalMargin = 0.5;  // pp
inline constexpr double kStudyLevel = 0.95;
// "The early part of the test" (conclusion 6), as in the one-seed report.
inline constexpr double kStudyEarlyTime = 3600;  // s
inline constexpr std::size_t kConclusions = 6;

enum class StudyVerdict { supports, contradicts, no_effect, inconclusive, not_run };
const char* to_string(StudyVerdict v);

struct Decision {
  StudyVerdict verdict = StudyVerdict::inconclusive;
  std::size_t seeds = 0;  // the interval's n
  // When inconclusive: the seeds at which an interval of the same spread would decide it
  // (0: fewer than two seeds, or no count up to a million is enough).
  std::size_t seeds_to_decide = 0;
  // A supporting or contradicting interval that lies inside the practical margin too: a
  // certain effect too small to matter. The rule, written first, keeps the verdict; the text
  // says so.
  bool inside_margin = false;
  // "supports", "inconclusive: ~37 seeds would decide it", "contradicts, inside +-0.5 pp", ...
  std::string text() const;
};

// The rule: supports when the interval excludes zero on the positive side, contradicts on
// the negative side, no effect when it lies within +-margin; otherwise inconclusive, with the
// least n at which an interval of this sd would exclude zero or fit inside the margin.
Decision decide(const Interval& effect, double margin = kPracticalMargin);

// The run folders of one seed: the five samples, and the same seed with the sphere and the
// pipette shallow and deep (empty when the depth runs were not made).
struct SeedRuns {
  double seed = 0;
  std::vector<RunFolder> runs, shallow, deep;
};

// The same runs with every test's DEM readings replaced by its reference readings: the
// laboratory test's own behaviour, free of the simulation's scatter.
SeedRuns reference_only(const SeedRuns& runs);

// The six effects of one seed, in pp (NaN where the runs hold no reading for it), and the
// buoyancy and pipette readings above 100 % (the paper's "local inhomogeneities").
struct SeedEffects {
  double seed = 0;
  std::array<double, kConclusions> dem{}, reference{};
  double above_100 = 0;
};
std::array<double, kConclusions> effects(const SeedRuns& runs, double early_s = kStudyEarlyTime);
SeedEffects seed_effects(const SeedRuns& runs, double early_s = kStudyEarlyTime);

// Each effect alone, as effects() computes it.
double size_range_effect(const std::vector<RunFolder>& runs);
double smoothing_effect(const std::vector<RunFolder>& runs);
double oscillation_effect(const std::vector<RunFolder>& runs);
double large_size_effect(const std::vector<RunFolder>& runs);
double depth_effect(const std::vector<RunFolder>& shallow, const std::vector<RunFolder>& deep);
double early_effect(const std::vector<RunFolder>& runs, double early_s);
std::size_t readings_above_100(const std::vector<RunFolder>& runs);

// One conclusion over the seeds of a regime.
struct StudyConclusion {
  std::size_t number = 0;  // 1..6
  std::string claim;
  Interval effect, scatter;  // scatter: DEM effect minus reference effect, per seed
  double reference = 0;      // the same for every seed; their mean
  Decision decision;
};
struct StudyRegime {
  std::string label;
  std::string note;  // what the runs were: seeds, samples, particles, simulated time
  std::vector<SeedEffects> seeds;
  std::array<StudyConclusion, kConclusions> conclusions;
  Interval above_100;
};
// `depth_run`: whether the regime had depth runs; without, conclusion 5 is "not run".
StudyRegime study_regime(const std::string& label, const std::vector<SeedEffects>& seeds,
                         bool depth_run);

// The paper's wording of conclusion k (1..6).
const std::string& study_claim(std::size_t k);

}  // namespace sedem::validation
