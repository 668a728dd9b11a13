#include "core/scene/stage_keys.h"

#include "core/scene/schema.h"

namespace sedem {

void describe(SampleConfig& c, Schema& s) {
  s.number("sample.particle_density", &c.particle_density, "kg/m^3", 1, 1001, 20000,
           "Density of the soil grains (must exceed the fluid's).");
  s.number("sample.mass_g", &c.total_mass, "g", 1e-3, 1e-3, 1000,
           "Dry soil mass poured into the whole cylinder (ASTM D422: 60 g).");
  s.integer("sample.size_count", &c.size_count, 1, 100000,
            "n_phi: discrete sizes the grading curve is cut into (paper: 220).");
  s.integer("sample.simulated_count", &c.simulated_count, 0, kMaxSimulatedCount,
            "Particles the engine moves; each stands for `weight` real grains. 0: derived "
            "from sample.mass_fraction (give one of the two).");
  s.number("sample.mass_fraction", &c.mass_fraction, "", 1, 0, 1,
           "Share of the section's soil mass simulated grain for grain (the particle count "
           "follows from it and the weighting); 0: use sample.simulated_count.");
  s.exclusive("sample.simulated_count", "sample.mass_fraction");
  s.choice("sample.weighting", &c.weighting, {"equal_mass", "uniform_count", "equal_per_size"},
           "How simulated particles share the real grains: equal real mass per particle, the "
           "same number of real grains per particle, or the same particle count per size.");
  s.integer("sample.seed", &c.seed, 0, INT64_MAX,
            "Seed of the random placement (same seed, same sample).");
  s.choice("sample.grading.family", &c.grading.family,
           {"table", "log_uniform", "log_normal", "rosin_rammler", "single"},
           "Shape of the grading curve: a table of points, a named family, or one size "
           "(single ignores sample.size_count).");
  s.list("sample.grading.diameters_um", &c.grading.diameters, "um", 1e-6, 0.01, 10000,
         "table: diameters, strictly ascending (percent finer interpolated linearly in log d).");
  s.list("sample.grading.percent_finer", &c.grading.percent_finer, "%", 1, 0, 100,
         "table: percent finer by mass at each diameter; non-decreasing, from 0 to 100.");
  s.number("sample.grading.min_um", &c.grading.min_diameter, "um", 1e-6, 0.01, 10000,
           "Named families: smallest diameter (the family is truncated to [min, max]).");
  s.number("sample.grading.max_um", &c.grading.max_diameter, "um", 1e-6, 0.01, 10000,
           "Named families: largest diameter.");
  s.number("sample.grading.median_um", &c.grading.median_diameter, "um", 1e-6, 0.01, 10000,
           "log_normal: d50 of the untruncated family; rosin_rammler: the scale d63.");
  s.number("sample.grading.spread", &c.grading.spread, "", 1, 1e-3, 100,
           "log_normal: standard deviation of ln d; rosin_rammler: uniformity exponent n.");
  s.number("sample.grading.diameter_um", &c.grading.diameter, "um", 1e-6, 0.01, 10000,
           "single: the one grain size.");
  s.choice("sample.placement.method", &c.placement.method, {"low_discrepancy", "stratified"},
           "low_discrepancy: the particles, finest first, on seeded R2 quasi-random points in "
           "near-square bands, so every size and every run of sizes is spread evenly across "
           "and down the section, as in the well-shaken suspension (the instruments then see "
           "a half to a third of the sampling noise); stratified: the paper's random points in an "
           "n_mt x n_mt matrix of cells (Fig. 6).");
  s.integer("sample.placement.cells_per_side", &c.placement.cells_per_side, 0, 100000,
            "stratified: n_mt, the section is cut into n_mt x n_mt cells of its own aspect "
            "ratio and the particles are spread evenly over them (Fig. 6); 0: ceil(sqrt(particle "
            "count)).");
  s.number("sample.placement.max_area_fraction", &c.placement.max_area_fraction, "", 1, 1e-6, 0.5,
           "Largest share of the section's plane the particles may cover; a denser scene is "
           "refused, as random placement without overlap cannot reach it reliably.");
}

}  // namespace sedem
