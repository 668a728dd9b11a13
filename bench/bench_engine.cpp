// sedem_bench_engine: throughput and stability of the DEM engine.
//
//   sedem_bench_engine [--out DIR] [--huge] [--quick] [--throughput-only]
//                      [--cases dilute,bed] [--counts 1000,1000000] [--particle-steps N]
//                      [--set key=value ...]
//
// Prints its figures and writes DIR/engine_throughput.csv and DIR/engine_stability.csv.
//  - throughput: particle-steps per second against particle count (1e3 ... 1e6; 1e7 with
//    --huge) for a dilute suspension in the paper's cylinder (2.5-70 um, Di Felice drag,
//    contacts with friction) and for a settled bed; heap bytes per particle.
//  - stability: step multipliers, K_N 0.1x-100x, friction 0-1, size ratios up to 28 and a dense
//    bed, each reporting the largest overlap, the energy growth, escaped particles and any
//    instability the engine detected.
//  - accuracy: the exponential integrator's error against the explicit one at growing steps.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "core/engine/engine.h"
#include "core/physics/stokes.h"
#include "core/run/stage_setups.h"
#include "core/scene/scene_loader.h"

namespace {

using namespace sedem;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// A dilute suspension: a jittered lattice filling the section, log-uniform sizes between
// d_min and d_max (capped so that lattice neighbours never overlap), equal statistical
// weights adding up to the paper's 60 g / 180.
Sample dilute(const Scene& scene, std::size_t n, double d_min, double d_max, unsigned seed) {
  const double b = scene.cylinder.diameter, h = scene.cylinder.height;
  const double spacing = std::sqrt(b * h / double(n));
  const auto cols = std::size_t(std::max(1.0, std::floor(b / spacing)));
  const double dx = b / double(cols);
  const double dy = h / std::ceil(double(n) / double(cols));
  d_max = std::min(d_max, 0.8 * std::min(dx, dy));
  d_min = std::min(d_min, d_max);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  Sample s;
  s.particles.resize(n);
  double mass = 0;
  for (std::size_t i = 0; i < n; ++i) {
    auto& p = s.particles;
    const double d = d_min * std::pow(d_max / d_min, u(rng));
    const double room_x = dx - d, room_y = dy - d;
    p.x[i] = -0.5 * b + double(i % cols) * dx + 0.5 * d + room_x * u(rng);
    p.y[i] = double(i / cols) * dy + 0.5 * d + room_y * u(rng);
    p.diameter[i] = d;
    p.id[i] = std::uint32_t(i);
    mass += 2500 * std::numbers::pi / 6 * d * d * d;
  }
  const double weight = 60e-3 / 180 / mass;
  for (auto& w : s.particles.weight) w = weight;
  return s;
}

// A settled bed: rows of touching grains on the bottom (sizes between d and d * ratio mixed
// by rows of small and large), the state the suspension ends in.
Sample bed(const Scene& scene, std::size_t n, double d, double ratio, unsigned seed) {
  const double b = scene.cylinder.diameter;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  Sample s;
  s.particles.resize(n);
  double y = 0, row_height = 0, x = -0.5 * b;
  for (std::size_t i = 0; i < n; ++i) {
    auto& p = s.particles;
    const double di = (ratio > 1 && u(rng) < 0.1) ? d * ratio : d * (1 + 0.2 * u(rng));
    if (x + di > 0.5 * b) {
      x = -0.5 * b;
      y += row_height;
      row_height = 0;
    }
    p.x[i] = x + 0.5 * di;
    p.y[i] = y + 0.5 * di;
    p.diameter[i] = di;
    p.weight[i] = 1;
    p.id[i] = std::uint32_t(i);
    x += di;
    row_height = std::max(row_height, di);
  }
  return s;
}

struct Outcome {
  double max_overlap = 0;    // / smaller radius
  double energy_growth = 0;  // largest kinetic energy / that of every grain at u_tr
  std::size_t escaped = 0;   // outside the walls, under the bottom or above the surface
  std::string instability;   // empty: none detected
  std::int64_t steps = 0;
  double wall = 0;
};

double terminal_energy(const Engine& e) {
  double k = 0;
  const auto& p = e.particles();
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double d = p.diameter[i];
    const double u = stokes::terminal_velocity(d, 2500, Fluid{});
    k += 0.5 * 2500 * std::numbers::pi / 6 * d * d * d * u * u;
  }
  return k;
}

Outcome run(const Scene& scene, Sample sample, double duration, int samples) {
  Outcome o;
  Engine engine(engine_setup(scene), std::move(sample));
  const double scale = terminal_energy(engine);
  const auto t0 = Clock::now();
  try {
    for (int k = 1; k <= samples; ++k) {
      engine.advance_to(duration * k / samples);
      o.energy_growth = std::max(o.energy_growth, engine.kinetic_energy() / scale);
    }
  } catch (const InstabilityError& e) {
    o.instability = e.what();
  }
  o.wall = seconds_since(t0);
  o.steps = engine.stats().steps;
  o.max_overlap = engine.stats().max_overlap_ratio;
  const auto& p = engine.particles();
  const double hw = scene.cylinder.half_width();
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double r = 0.5 * p.diameter[i];
    if (!std::isfinite(p.x[i]) || std::abs(p.x[i]) > hw + r || p.y[i] < -r ||
        p.y[i] > scene.cylinder.height + r)
      ++o.escaped;
  }
  return o;
}

// Keys every benchmark scene takes from --set (e.g. --set forces.drag=stokes).
std::vector<std::string> g_overrides;

Scene base_scene(const std::string& method, int threads = 0) {
  Scene s = parse_scene("", "sedem_bench_engine --set", g_overrides);
  s.integrator.threads = threads;
  s.integrator.method = method;
  s.integrator.freeze_settled = false;
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  std::string out = ".";
  bool huge = false, quick = false, throughput_only = false;
  std::vector<std::string> cases{"dilute", "bed"};
  std::vector<std::size_t> chosen_counts;
  double target = 6e7;  // particle-steps per measurement (spans list rebuilds)
  auto split = [](const std::string& list) {
    std::vector<std::string> items;
    std::stringstream in(list);
    for (std::string item; std::getline(in, item, ',');) items.push_back(item);
    return items;
  };
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if (arg == "--out" && a + 1 < argc)
      out = argv[++a];
    else if (arg == "--huge")
      huge = true;
    else if (arg == "--quick")
      quick = true;
    else if (arg == "--throughput-only")
      throughput_only = true;
    else if (arg == "--cases" && a + 1 < argc)
      cases = split(argv[++a]);
    else if (arg == "--particle-steps" && a + 1 < argc)
      target = std::stod(argv[++a]);
    else if (arg == "--set" && a + 1 < argc)
      g_overrides.push_back(argv[++a]);
    else if (arg == "--counts" && a + 1 < argc)
      for (const std::string& c : split(argv[++a])) chosen_counts.push_back(std::stoul(c));
    else {
      std::fprintf(stderr,
                   "usage: %s [--out DIR] [--huge] [--quick] [--throughput-only] "
                   "[--cases dilute,bed] [--counts N,...] [--particle-steps N] [--set key=value]\n",
                   argv[0]);
      return 2;
    }
  }
  std::filesystem::create_directories(out);

  // Throughput.
  std::ofstream tcsv(out + "/engine_throughput.csv");
  tcsv << "case,particles,threads,step_s,steps,list_builds,wall_s,particle_steps_per_s,"
          "bytes_per_particle\n";
  std::printf("%-8s %10s %8s %10s %8s %8s %14s %10s\n", "case", "particles", "threads", "step_s",
              "steps", "rebuilds", "psteps/s", "B/particle");
  std::vector<std::size_t> counts{1000, 10000, 100000, 1000000};
  if (quick) counts = {1000, 10000, 100000};
  if (huge) counts.push_back(10000000);
  if (!chosen_counts.empty()) counts = chosen_counts;
  for (const std::string& kind : cases) {
    for (std::size_t n : counts) {
      Scene scene = base_scene("exponential");
      Sample sample =
          kind == "dilute" ? dilute(scene, n, 2.5e-6, 70e-6, 1) : bed(scene, n, 10e-6, 1, 1);
      Engine engine(engine_setup(scene), std::move(sample));
      engine.step(1e9);  // warm-up: first-touch of every buffer
      const auto steps = std::max<std::int64_t>(3, std::int64_t(target / double(n)));
      const auto before = engine.stats();
      const auto t0 = Clock::now();
      for (std::int64_t k = 0; k < steps; ++k) engine.step(1e9);
      const double wall = seconds_since(t0);
      const double ps = (engine.stats().particle_steps - before.particle_steps) / wall;
      const double bpp = double(engine.bytes()) / double(n);
      const auto builds = engine.stats().list_builds - before.list_builds;
      std::printf("%-8s %10zu %8d %10.3g %8lld %8lld %14.4g %10.1f\n", kind.c_str(), n,
                  engine.threads(), engine.stats().last_step, static_cast<long long>(steps),
                  static_cast<long long>(builds), ps, bpp);
      tcsv << kind << ',' << n << ',' << engine.threads() << ',' << engine.stats().last_step << ','
           << steps << ',' << builds << ',' << wall << ',' << ps << ',' << bpp << '\n';
      std::fflush(stdout);
    }
  }

  if (throughput_only) return 0;

  // Stability sweep: small systems on one thread, each run for a short simulated time.
  std::ofstream scsv(out + "/engine_stability.csv");
  scsv << "sweep,value,case,particles,steps,wall_s,max_overlap_ratio,energy_growth,escaped,"
          "instability\n";
  std::printf("\n%-14s %8s %-7s %8s %12s %12s %8s %s\n", "sweep", "value", "case", "steps",
              "max_overlap", "energy_x", "escaped", "instability");
  auto report = [&](const char* sweep, double value, const char* kind, std::size_t n,
                    const Outcome& o) {
    std::printf("%-14s %8g %-7s %8lld %12.3g %12.3g %8zu %s\n", sweep, value, kind,
                static_cast<long long>(o.steps), o.max_overlap, o.energy_growth, o.escaped,
                o.instability.empty() ? "none" : o.instability.c_str());
    scsv << sweep << ',' << value << ',' << kind << ',' << n << ',' << o.steps << ',' << o.wall
         << ',' << o.max_overlap << ',' << o.energy_growth << ',' << o.escaped << ",\""
         << o.instability << "\"\n";
    std::fflush(stdout);
  };
  const std::size_t small = quick ? 1000 : 3000;
  const double horizon = quick ? 0.05 : 0.2;
  for (double factor : {10.0, 100.0, 1000.0, 10000.0}) {
    Scene scene = base_scene("exponential", 1);
    scene.integrator.fast_step_factor = factor;
    report("step_factor", factor, "dilute", small,
           run(scene, dilute(scene, small, 2.5e-6, 70e-6, 2), horizon, 10));
    report("step_factor", factor, "bed", small,
           run(scene, bed(scene, small, 10e-6, 1, 2), horizon, 10));
  }
  for (double kn : {0.1, 1.0, 10.0, 100.0}) {
    Scene scene = base_scene("exponential", 1);
    scene.forces.stiffness_normal = scene.forces.stiffness_tangential = 1e3 * kn;
    report("stiffness_x", kn, "bed", small,
           run(scene, bed(scene, small, 10e-6, 1, 3), horizon, 10));
  }
  for (double mu : {0.0, 0.25, 0.5, 1.0}) {
    Scene scene = base_scene("exponential", 1);
    scene.forces.friction = mu;
    report("friction", mu, "bed", small, run(scene, bed(scene, small, 10e-6, 1, 4), horizon, 10));
  }
  for (double ratio : {1.0, 4.0, 10.0, 28.0}) {
    Scene scene = base_scene("exponential", 1);
    report("size_ratio", ratio, "bed", small,
           run(scene, bed(scene, small, 2.5e-6, ratio, 5), horizon, 10));
  }
  {
    // A dense bed: many rows of mixed 2.5-70 um grains poured on each other, lubrication on.
    Scene scene = base_scene("exponential", 1);
    scene.forces.lubrication = true;
    report("dense_bed", 28, "bed", 4 * small,
           run(scene, bed(scene, 4 * small, 2.5e-6, 28, 6), horizon, 10));
  }
  {
    // The explicit integrator on the same dilute suspension, for comparison (short).
    Scene scene = base_scene("explicit", 1);
    report("explicit", 0.1, "dilute", 300,
           run(scene, dilute(scene, 300, 2.5e-6, 70e-6, 7), 2e-3, 4));
  }

  // Accuracy: dilute suspension, exponential against the explicit integrator at a fine step.
  {
    std::printf("\n%-12s %12s %10s %16s\n", "step_factor", "x explicit", "steps",
                "max error / fall");
    std::ofstream acsv(out + "/engine_accuracy.csv");
    acsv << "fast_step_factor,step_multiple_of_explicit,steps,max_position_error_over_fall\n";
    const double t = 0.01;
    Scene rs = base_scene("explicit");
    rs.integrator.adaptive = false;
    rs.integrator.step_factor = 0.01;
    Sample s0 = dilute(rs, 400, 5e-6, 70e-6, 8);
    Engine ref(engine_setup(rs), s0);
    ref.advance_to(t);
    const double fall = stokes::terminal_velocity(70e-6, 2500, Fluid{}) * t;
    for (double factor : {1000.0, 100.0, 10.0, 1.0}) {
      Scene fs = base_scene("exponential");
      fs.integrator.fast_step_factor = factor;
      Engine fast(engine_setup(fs), s0);
      fast.advance_to(t);
      double err = 0;
      for (std::size_t i = 0; i < s0.particles.size(); ++i)
        err = std::max(err, std::hypot(fast.particles().x[i] - ref.particles().x[i],
                                       fast.particles().y[i] - ref.particles().y[i]));
      // The step actually taken (capped at r_min / u_max) over the explicit integrator's first
      // step.
      const double first = 0.1 * stokes::response_time(5e-6, 2500, Fluid{}, 0.95);
      const double multiple = t / double(fast.stats().steps) / first;
      std::printf("%-12g %12.4g %10lld %16.3g\n", factor, multiple,
                  static_cast<long long>(fast.stats().steps), err / fall);
      acsv << factor << ',' << multiple << ',' << fast.stats().steps << ',' << err / fall << '\n';
    }
  }
  std::printf("\nCSV written to %s\n", out.c_str());
  return 0;
}
