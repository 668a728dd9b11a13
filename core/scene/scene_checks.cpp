#include "core/scene/scene_checks.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/instruments/buoyancy_sphere.h"
#include "core/instruments/hydrometer.h"
#include "core/instruments/pipette.h"
#include "core/instruments/plausibility.h"
#include "core/physics/stokes.h"
#include "core/sample/grading_curve.h"
#include "core/sample/placement.h"
#include "core/sample/sample_builder.h"
#include "core/sample/sample_checks.h"
#include "core/scene/scene.h"
#include "core/scene/scene_loader.h"

namespace sedem {

std::string SceneOrigins::of(const std::string& key) const {
  auto it = at.find(key);
  return it != at.end() ? it->second : source + " (default)";
}

namespace {

class Checker {
 public:
  Checker(const Scene& scene, const SceneOrigins& origins)
      : copy_(scene), schema_(copy_.schema()), origins_(origins) {}

  // "<where>: <key> = <value> <what>"
  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    throw SceneError(origins_.of(key) + ": " + key + " = " + value(key) + " " + what);
  }
  std::string value(const std::string& key) const {
    const Param* p = schema_.find(key);
    return p ? shortened(format_user_value(*p)) : "?";
  }

 private:
  Scene copy_;  // the schema binds to a scene it may point into; the checked one is const
  Schema schema_;
  const SceneOrigins& origins_;
};

std::string number(double v) {
  std::ostringstream os;
  os.precision(6);
  os << v;
  return os.str();
}

void check_table(const GradingConfig& g, const Checker& check) {
  const char* kD = "sample.grading.diameters_um";
  const char* kP = "sample.grading.percent_finer";
  if (g.diameters.size() < 2)
    check.fail(kD, "needs at least 2 diameters (the smallest and the largest of the sample)");
  if (g.diameters.size() != g.percent_finer.size())
    check.fail(kP, "has " + std::to_string(g.percent_finer.size()) + " values but " +
                       std::string(kD) + " has " + std::to_string(g.diameters.size()) +
                       "; give one percentage per diameter");
  for (std::size_t i = 1; i < g.diameters.size(); ++i) {
    if (!(g.diameters[i] > g.diameters[i - 1]))
      check.fail(kD, "must be strictly ascending (" + number(g.diameters[i] * 1e6) + " follows " +
                         number(g.diameters[i - 1] * 1e6) + ")");
    if (g.percent_finer[i] < g.percent_finer[i - 1])
      check.fail(kP, "must not decrease (" + number(g.percent_finer[i]) + " follows " +
                         number(g.percent_finer[i - 1]) + ")");
  }
  if (g.percent_finer.front() != 0)
    check.fail(kP, "must start at 0: nothing is finer than the smallest diameter");
  if (g.percent_finer.back() != 100)
    check.fail(kP, "must end at 100: everything is finer than the largest diameter");
}

void check_family(const GradingConfig& g, const Checker& check) {
  if (!(g.min_diameter < g.max_diameter))
    check.fail("sample.grading.min_um", "must be smaller than sample.grading.max_um = " +
                                            check.value("sample.grading.max_um"));
  const GradingCurve curve(g);
  if (!(curve.captured_share() >= 1e-6))
    check.fail("sample.grading.median_um",
               "with sample.grading.spread = " + check.value("sample.grading.spread") +
                   " leaves almost none (" + number(curve.captured_share()) + ") of the " +
                   g.family + " curve's mass between min_um and max_um; move median_um into " +
                   "the range or widen the spread");
}

// Each enabled instrument must fit in the column and work in the scene's liquid: the checks
// the instruments would otherwise make at their first reading, made before anything runs.
void check_instruments(const Scene& scene, const Checker& check) {
  const auto& in = scene.instruments;
  const Cylinder& c = scene.cylinder;
  const bool any = in.hydrometer || in.buoyancy || in.pipette;
  if (any && scene.forces.drag == "off")
    check.fail("forces.drag",
               "gives no terminal velocity, which the instruments' reference solution needs; "
               "choose di_felice or stokes, or disable the instruments");
  if (in.buoyancy) {
    const double r = 0.5 * in.sphere_diameter, depth = in.buoyancy_depth_fraction * c.height;
    if (2 * r > c.height || 2 * r > c.diameter)
      check.fail(2 * r > c.height ? "cylinder.height_m" : "cylinder.diameter_m",
                 "is too small for the buoyancy sphere (instruments.buoyancy.sphere_diameter_cm "
                 "= " +
                     check.value("instruments.buoyancy.sphere_diameter_cm") +
                     "); make the column larger or set instruments.buoyancy.enabled = false");
    if (depth - r < 0 || depth + r > c.height)
      check.fail("instruments.buoyancy.depth_fraction",
                 "puts the sphere (" + number(2 * r * 100) +
                     " cm) partly outside the liquid; allowed for this column: " +
                     number(r / c.height) + " to " + number(1 - r / c.height));
  }
  if (in.pipette) {
    Pipette p;
    p.volume = in.pipette_volume;
    p.depth = in.pipette_depth_fraction * c.height;
    const double r = p.radius(c);
    if (r > c.half_width() || 2 * r > c.height)
      check.fail("instruments.pipette.volume_ml",
                 "needs a sampling circle of radius " + number(r * 100) +
                     " cm, which does not fit in the section (" + number(c.diameter * 100) +
                     " cm x " + number(c.height * 100) + " cm)");
    if (p.depth - r < 0 || p.depth + r > c.height)
      check.fail("instruments.pipette.depth_fraction",
                 "puts the sampling circle (radius " + number(r * 100) +
                     " cm) partly outside the liquid; allowed for this column: " +
                     number(r / c.height) + " to " + number(1 - r / c.height));
  }
  if (in.hydrometer) {
    HydrometerDesign design;
    design.tip_length = in.hydrometer_tip_length;
    design.shoulder_length = in.hydrometer_shoulder_length;
    if (design.tip_length + design.shoulder_length > design.bulb_length)
      check.fail("instruments.hydrometer.tip_length_cm",
                 "with instruments.hydrometer.shoulder_length_cm = " +
                     check.value("instruments.hydrometer.shoulder_length_cm") +
                     " is longer than the 14 cm bulb");
    const HydrometerGeometry h = make_hydrometer(design);
    const double lightest = h.mass / h.volume_below(h.length());
    if (!(scene.fluid.density > lightest))
      check.fail("fluid.density",
                 "is too light for the 152H hydrometer, which sinks in it (it "
                 "floats in liquids denser than " +
                     number(lightest) + " kg/m^3)");
    const double tip = tip_depth_in_uniform(h, scene.fluid.density);
    const double bulb_top = tip - h.bulb_length;
    const double reading = h.reading_at(bulb_top);
    if (bulb_top < 0 || reading < h.scale_min || reading > h.scale_max)
      check.fail("fluid.density",
                 "puts the 152H hydrometer off its scale before any soil is added: it would read "
                 "R = " +
                     number(reading) + " g/L in the clear liquid (scale " + number(h.scale_min) +
                     " to " + number(h.scale_max) + ")" +
                     (bulb_top < 0 ? ", with the top of its bulb " + number(-bulb_top * 100) +
                                         " cm above the surface"
                                   : std::string()));
    if (tip >= c.height)
      check.fail("cylinder.height_m", "is shorter than the depth the 152H hydrometer floats at (" +
                                          number(tip * 100) +
                                          " cm in the clear liquid): it would touch the bottom");
  }
}

// An enabled instrument whose sampled volume holds on average less than one simulated particle
// at the start reads noise alone: refused, naming the key that sizes the volume, or the
// particle count when that key was left at its default. Fewer than kDoubtfulSampled is only
// doubtful: a warning when the run starts (setup_doubts).
void check_sampled_volumes(const Scene& scene, const SceneOrigins& origins, const Checker& check) {
  TestSetup setup;
  setup.cylinder = scene.cylinder;
  setup.instruments = scene.instruments;
  const double count =
      double(plan_sample(SampleSetup{scene.sample, scene.cylinder}).simulated_total);
  for (const auto& v : sampled_volumes(setup, count)) {
    if (v.particles >= kMinSampled) continue;
    const bool own_key = origins.at.count(v.key) > 0;
    const std::string key = own_key ? v.key : "sample.simulated_count";
    // Each key scales the share linearly: the pipette's volume, the sphere's diameter, the
    // column's height inversely (the bulb's share of it).
    const double need = kMinSampled / v.particles;
    std::string allowed;
    if (!own_key)
      allowed = ">= " + number(std::ceil(count * need));
    else if (v.test == "pipette")
      allowed = ">= " + number(scene.instruments.pipette_volume * need * 1e6) + " mL";
    else if (v.test == "buoyancy")
      allowed = ">= " + number(scene.instruments.sphere_diameter * need * 100) + " cm";
    else
      allowed = "<= " + number(scene.cylinder.height / need) + " m";
    check.fail(key, "leaves about " + number(v.particles) + " of the " + number(count) +
                        " simulated particles in the " + v.test +
                        "'s sampled volume at the start (" + number(100 * v.share) +
                        " % of the section): its readings would be noise alone; allowed for "
                        "this scene: " +
                        allowed + " (or instruments." + v.test + ".enabled = false)");
  }
}

// The most coasting windows a run may take (each free grain syncs at least every
// integrator.max_coast_s while it is in suspension): hours of computing; a million particles of
// sample 5 over 24 h at the default 60 s take about 1e8. More is no progress: the engine would
// spend hours at t = 0 between two looks for a stop (a window far shorter than the test).
inline constexpr double kMaxCoastWindows = 1e10;

void check_coasting(const Scene& scene, const Checker& check) {
  const auto& in = scene.integrator;
  if (in.method != "exponential" || !in.local_steps || !(scene.end_time > 0)) return;
  const SamplePlan plan = plan_sample(SampleSetup{scene.sample, scene.cylinder});
  // A grain syncs while it is in suspension: until it has fallen the column's height at its
  // clear-water speed (hindered settling is slower by a few per cent at these solids), or the
  // whole test. Counting every grain over the whole test refused 10^7 particles that take
  // 5e8 windows as if they took 1.4e10.
  double grain_seconds = 0;
  for (const SizeClass& c : plan.classes) {
    const double speed =
        stokes::terminal_velocity(c.diameter, scene.sample.particle_density, scene.fluid);
    const double stay =
        speed > 0 ? std::min(scene.end_time, scene.cylinder.height / speed) : scene.end_time;
    grain_seconds += double(c.simulated_count) * stay;
  }
  const double windows = grain_seconds / in.max_coast;
  if (windows > kMaxCoastWindows)
    check.fail("integrator.max_coast_s",
               "makes " + number(double(plan.simulated_total)) + " particles take about " +
                   number(windows) +
                   " coasting windows over run.end_time_s = " + check.value("run.end_time_s") +
                   ": hours of computing with no progress; allowed for this scene: >= " +
                   number(grain_seconds / kMaxCoastWindows) + " s");
}

}  // namespace

void check_scene(const Scene& scene, const SceneOrigins& origins) {
  const Checker check(scene, origins);
  const auto& s = scene.sample;
  if (s.particle_density <= scene.fluid.density)
    check.fail("sample.particle_density",
               "must exceed fluid.density = " + check.value("fluid.density") +
                   " kg/m^3, or nothing settles");

  if (!(scene.fluid.gravity > 0))
    check.fail("fluid.gravity",
               "leaves the grains floating: nothing settles and no test can be "
               "read; give a positive value (9.81 on Earth)");
  if (scene.name.size() > kMaxNameLength)
    throw SceneError(origins.of("name") + ": name is " + std::to_string(scene.name.size()) +
                     " characters long; at most " + std::to_string(kMaxNameLength) +
                     " are allowed");

  const auto& g = s.grading;
  if (g.family == "table")
    check_table(g, check);
  else if (g.family != "single")
    check_family(g, check);

  const GradingCurve curve(g);
  const double room = std::min(scene.cylinder.diameter, scene.cylinder.height);
  if (curve.max_diameter() > room)
    check.fail("cylinder.diameter_m",
               "is smaller than the largest grain (" + number(curve.max_diameter() * 1e6) + " um)");

  if (s.simulated_count == 0 && s.mass_fraction == 0)
    check.fail("sample.simulated_count",
               "and sample.mass_fraction = 0: give one of them (a particle count, or the share "
               "of the section's soil to simulate)");

  try {
    check_sample(SampleSetup{scene.sample, scene.cylinder});
  } catch (const SetupProblem& p) {
    check.fail(p.key, p.problem);
  }

  const bool retiring = scene.integrator.method == "exponential" && scene.integrator.local_steps &&
                        scene.integrator.retire_below && any_instrument(scene.instruments);
  if (!scene.forces.suspension_contacts && !retiring)
    check.fail("forces.suspension_contacts",
               "needs grains to retire onto the coarse bed below the instruments "
               "(integrator.method = exponential, integrator.local_steps = true, "
               "integrator.retire_below_instruments = true, an instrument enabled): grains "
               "that passed each other would reach a contact bed overlapping");
  if (scene.integrator.carried_substeps && !(scene.integrator.carried_fraction > 0))
    check.fail("integrator.carried_substeps",
               "needs carried steps: set integrator.carried_fraction in (0, 1] (0.8 lets "
               "the step be what the coarse grains alone allow)");
  if (scene.integrator.own_steps &&
      !(scene.integrator.method == "exponential" && scene.integrator.local_steps &&
        scene.forces.suspension_contacts && !(scene.integrator.carried_fraction > 0)))
    check.fail("integrator.own_steps",
               "needs integrator.method = exponential, integrator.local_steps = true, "
               "forces.suspension_contacts = true and integrator.carried_fraction = 0 (clusters "
               "of members on steps of their own are an alternative to carried steps)");
  const double box_steps = scene.integrator.member_box_steps;
  if (box_steps != 0 && !(box_steps >= 2))
    check.fail("integrator.member_box_steps",
               "must be 0 (boxes of 2 radii) or at least 2 (below 2 the step grows back too "
               "slowly after a pushed grain leaves; at 1 it could never grow)");
  check_instruments(scene, check);
  check_sampled_volumes(scene, origins, check);
  check_coasting(scene, check);
}

}  // namespace sedem
