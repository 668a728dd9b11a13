// What a second thread costs on this machine, against what a pass over grains gives it.
//
// Where grains meet, the members' step runs its passes (lists, free update, the projection's
// collection) on the engine's threads from 256 members, but between them come parts on one
// thread (the syncs, the projection's sweeps, the step's own loops) that read every member: each
// member's cache lines then cross between the cores twice a step. This program measures the
// primitives (a barrier, an empty parallel region, a cache line handed to the other core and
// back) and a member-like pass (five doubles a grain and an exponential, as the free update)
// threaded on its own and threaded between two passes on one thread, against the same on one
// thread, for grain counts from 64 to a million. docs/results/engine.md, "Two threads where
// grains meet, measured again", reads it.
//
//   sedem_bench_thread_costs [--threads N] [--counts 64,256,...] [--out DIR]
#include <omp.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Microseconds per call of `body(reps)`, doubling reps until a run takes 0.2 s.
template <class Body>
double microseconds_per(Body&& body) {
  for (long reps = 64;; reps *= 2) {
    const Clock::time_point t0 = Clock::now();
    body(reps);
    const double s = seconds_since(t0);
    if (s >= 0.2) return 1e6 * s / double(reps);
  }
}

struct Primitives {
  double barrier_us = 0, region_us = 0, round_trip_us = 0;
};

Primitives primitives(int threads) {
  Primitives p;
  p.barrier_us = microseconds_per([&](long reps) {
#pragma omp parallel num_threads(threads)
    for (long i = 0; i < reps; ++i) {
#pragma omp barrier
    }
  });
  p.region_us = microseconds_per([&](long reps) {
    for (long i = 0; i < reps; ++i) {
#pragma omp parallel num_threads(threads)
      { asm volatile("" ::: "memory"); }
    }
  });
  // One line handed from the first thread to the second and back.
  p.round_trip_us = microseconds_per([&](long reps) {
    std::atomic<long> turn{0};
#pragma omp parallel num_threads(2)
    {
      const long me = omp_get_thread_num();
      for (long i = 0; i < reps; ++i) {
        while (turn.load(std::memory_order_acquire) != 2 * i + me) {
        }
        turn.fetch_add(1, std::memory_order_acq_rel);
      }
    }
  });
  return p;
}

// Five doubles a grain, updated as the free update does (an exponential decay over the step).
struct Grains {
  std::vector<double> x, y, vx, vy, rate;
  explicit Grains(std::size_t n) : x(n, 0.0), y(n, 0.0), vx(n, 1e-4), vy(n, -1e-3), rate(n) {
    for (std::size_t i = 0; i < n; ++i) rate[i] = 1e3 * (1 + double(i % 97));
  }
};

void free_update(Grains& g, int threads) {
  const long n = long(g.x.size());
  const double dt = 1e-5;
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1)
  for (long i = 0; i < n; ++i) {
    const double lost = std::expm1(-g.rate[i] * dt);
    const double relax = -lost / g.rate[i];
    g.x[i] += g.vx[i] * relax;
    g.y[i] += g.vy[i] * relax;
    g.vx[i] *= 1 + lost;
    g.vy[i] *= 1 + lost;
  }
}

// A pass on one thread that reads and writes every grain's position, as a sweep or a step's
// own loop does.
double serial_pass(Grains& g) {
  double sum = 0;
  for (std::size_t i = 0; i < g.x.size(); ++i) {
    sum += g.x[i];
    g.y[i] += 1e-15 * g.x[i];
  }
  return sum;
}

struct PassTimes {
  std::size_t grains = 0;
  double alone_one = 0, alone_threads = 0, between_one = 0, between_threads = 0;
};

PassTimes pass_times(std::size_t n, int threads) {
  PassTimes t;
  t.grains = n;
  Grains g(n);
  volatile double sink = 0;
  auto alone = [&](int th) {
    return microseconds_per([&](long reps) {
      for (long r = 0; r < reps; ++r) free_update(g, th);
    });
  };
  auto between = [&](int th) {
    return microseconds_per([&](long reps) {
      for (long r = 0; r < reps; ++r) {
        free_update(g, th);
        sink = sink + serial_pass(g);
      }
    });
  };
  t.alone_one = alone(1);
  t.alone_threads = alone(threads);
  t.between_one = between(1);
  t.between_threads = between(threads);
  return t;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"sedem thread costs: what a second thread costs against what a pass gives it"};
  int threads = 2;
  std::vector<std::size_t> counts{64, 256, 1024, 4096, 16384, 65536, 262144, 1048576};
  std::string out = "bench-out";
  app.add_option("--threads", threads, "Threads of the threaded runs")
      ->check(CLI::Range(2, 256))
      ->capture_default_str();
  app.add_option("--counts", counts, "Grain counts of the passes")->check(CLI::PositiveNumber);
  app.add_option("--out", out, "Folder for thread_costs.csv and thread_passes.csv")
      ->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  fs::create_directories(out);

  const Primitives p = primitives(threads);
  std::printf(
      "%d threads: a barrier %.3f us, an empty parallel region %.3f us, a cache line to "
      "the other core and back %.3f us\n",
      threads, p.barrier_us, p.region_us, p.round_trip_us);
  std::ofstream costs(fs::path(out) / "thread_costs.csv");
  costs << "threads,barrier_us,region_us,round_trip_us\n"
        << threads << ',' << p.barrier_us << ',' << p.region_us << ',' << p.round_trip_us << '\n';

  std::printf("%10s %26s %8s %26s %8s\n", "grains", "pass alone: 1 / N thr (us)", "ratio",
              "between serial: 1 / N (us)", "ratio");
  std::ofstream passes(fs::path(out) / "thread_passes.csv");
  passes << "grains,threads,alone_one_us,alone_threads_us,alone_ratio,between_one_us,"
            "between_threads_us,between_ratio\n";
  for (std::size_t n : counts) {
    const PassTimes t = pass_times(n, threads);
    const double alone = t.alone_one / t.alone_threads, between = t.between_one / t.between_threads;
    std::printf("%10zu %12.2f / %11.2f %8.2f %12.2f / %11.2f %8.2f\n", n, t.alone_one,
                t.alone_threads, alone, t.between_one, t.between_threads, between);
    passes << n << ',' << threads << ',' << t.alone_one << ',' << t.alone_threads << ',' << alone
           << ',' << t.between_one << ',' << t.between_threads << ',' << between << '\n';
  }
  std::printf("wrote %s/thread_costs.csv and thread_passes.csv\n", out.c_str());
  return 0;
}
