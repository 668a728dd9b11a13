#include "core/sample/sample_config.h"

#include "core/scene/schema.h"

namespace sedem {

void describe(SampleConfig& c, Schema& s) {
  s.number("sample.particle_density", &c.particle_density, "kg/m^3", 1, 1001, 20000,
           "Density of the soil grains (must exceed the fluid's).");
  s.number("sample.mass_g", &c.total_mass, "g", 1e-3, 1e-3, 1000,
           "Dry soil mass poured into the whole cylinder (ASTM D422: 60 g).");
  s.integer("sample.size_count", &c.size_count, 1, 100000,
            "n_phi: discrete sizes the grading curve is cut into (paper: 220).");
  s.integer("sample.simulated_count", &c.simulated_count, 1, 100000000,
            "Particles the engine moves; each stands for `weight` real grains.");
  s.choice("sample.weighting", &c.weighting, {"equal_mass", "uniform_count"},
           "How simulated particles share the real grains: equal mass per particle, or the "
           "same number of real grains per particle.");
  s.integer("sample.seed", &c.seed, 0, INT64_MAX, "Seed of the random placement.");
  s.choice("sample.grading.family", &c.grading.family,
           {"table", "log_uniform", "log_normal", "rosin_rammler"},
           "Shape of the grading curve: a table of points or a named family.");
  s.list("sample.grading.diameters_um", &c.grading.diameters, "um", 1e-6, 0.01, 10000,
         "Table: diameters, ascending (percent finer interpolated linearly in log d).");
  s.list("sample.grading.percent_finer", &c.grading.percent_finer, "%", 1, 0, 100,
         "Table: percent finer by mass at each diameter; non-decreasing, last = 100.");
  s.number("sample.grading.min_um", &c.grading.min_diameter, "um", 1e-6, 0.01, 10000,
           "Smallest diameter of a named family.");
  s.number("sample.grading.max_um", &c.grading.max_diameter, "um", 1e-6, 0.01, 10000,
           "Largest diameter of a named family.");
  s.number("sample.grading.median_um", &c.grading.median_diameter, "um", 1e-6, 0.01, 10000,
           "log_normal: d50; rosin_rammler: the scale d63.");
  s.number("sample.grading.spread", &c.grading.spread, "", 1, 1e-3, 100,
           "log_normal: standard deviation of ln d; rosin_rammler: uniformity exponent n.");
}

}  // namespace sedem
