#pragma once

// Grading curves of the shapes a laboratory meets, drawn at random within each shape's range,
// for the inversion's round trip on curves that no part of sedem was tuned to: narrow (a knee:
// most of the mass within a factor of 1.2-1.5 in size), gap-graded (no mass over a factor of
// 2-4), bimodal (two log-normal modes), log-uniform, and clay-heavy (40-70 % finer than 2 um).
// Each is a table of (diameter, percent finer) points, linear in log d between them, as
// `sample.grading` takes it.

#include <cstdint>
#include <string>
#include <vector>

namespace sedem::bench {

struct HiddenCurve {
  std::string name;                 // shape and variant, e.g. "bimodal-2"
  std::vector<double> diameter_um;  // increasing
  std::vector<double> percent_finer;
  // The scene keys that give a sample this curve (sample.grading.*).
  std::vector<std::string> overrides() const;
};

inline const std::vector<std::string> kHiddenShapes{"narrow", "gap-graded", "bimodal",
                                                    "log-uniform", "clay-heavy"};

// `variants` curves of every shape, drawn from `seed`.
std::vector<HiddenCurve> hidden_curves(int variants, std::uint64_t seed);

}  // namespace sedem::bench
