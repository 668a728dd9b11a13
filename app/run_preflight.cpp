#include "app/run_preflight.h"

#include <sys/resource.h>
#include <unistd.h>

#include <omp.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include "core/run/stage_setups.h"
#include "core/sample/sample_builder.h"

namespace sedem::app {
namespace fs = std::filesystem;

namespace {

// Bytes per simulated particle over the whole run: the engine's arrays (about 200, see
// docs/engine.md), the sample and its copies, the snapshots queued between the engine and
// the observers, the neighbour lists and the placement's grid. Measured peaks are 300 to 700.
constexpr double kBytesPerParticle = 1500;
// Bytes per voidage cell and worker thread beyond the four per-cell arrays.
constexpr double kBytesPerVoidageCell = 4 * sizeof(double);
// Fixed costs: the program, VTK, Qt, the renderer's buffers.
constexpr double kBaseBytes = 200e6;

std::string gigabytes(double bytes) {
  std::ostringstream os;
  os.precision(3);
  os << bytes / 1e9 << " GB";
  return os.str();
}

std::size_t meminfo_available() {
  std::ifstream in("/proc/meminfo");
  std::string name;
  std::size_t kb = 0;
  std::string unit;
  while (in >> name >> kb >> unit)
    if (name == "MemAvailable:") return kb * 1024;
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGESIZE);
  return pages > 0 && page > 0 ? std::size_t(pages) * std::size_t(page) : SIZE_MAX;
}

}  // namespace

std::size_t estimate_run_bytes(const Scene& scene, std::string* key) {
  const double particles = double(plan_sample(sample_setup(scene)).simulated_total);
  const double particle_bytes = particles * kBytesPerParticle;
  double grid_bytes = 0;
  if (scene.forces.drag == "di_felice") {
    const double cell = scene.forces.voidage_cell;
    const double cells =
        std::ceil(scene.cylinder.diameter / cell) * std::ceil(scene.cylinder.height / cell);
    const int threads =
        scene.integrator.threads > 0 ? int(scene.integrator.threads) : omp_get_max_threads();
    grid_bytes = cells * (kBytesPerVoidageCell + double(threads) * sizeof(double));
  }
  // Layer fields: a handful of arrays per snapshot and instrument.
  const double layer_bytes = double(scene.instruments.layers) * 16 * sizeof(double);
  const double frame_bytes = double(scene.output.frame_width * scene.output.frame_height) * 16;
  if (key)
    *key = grid_bytes > particle_bytes        ? "forces.voidage_cell_mm"
           : scene.sample.simulated_count > 0 ? "sample.simulated_count"
                                              : "sample.mass_fraction";
  return std::size_t(kBaseBytes + particle_bytes + grid_bytes + layer_bytes + frame_bytes);
}

std::size_t usable_memory_bytes() {
  std::size_t limit = meminfo_available();
  rlimit as{};
  if (::getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY) {
    // The limit counts the address space already taken (libraries, Qt, VTK).
    std::size_t taken = 0;
    std::ifstream statm("/proc/self/statm");
    if (statm >> taken) taken *= std::size_t(::sysconf(_SC_PAGESIZE));
    const std::size_t cap = std::size_t(as.rlim_cur);
    limit = std::min(limit, cap > taken ? cap - taken : 0);
  }
  return limit;
}

std::string memory_refusal(const Scene& scene) {
  std::string key;
  const std::size_t need = estimate_run_bytes(scene, &key);
  const std::size_t have = usable_memory_bytes();
  if (need <= have) return {};
  return "the run needs about " + gigabytes(double(need)) + " of memory and this machine has " +
         gigabytes(double(have)) + " available (" + key +
         " decides most of it); lower it, or run on a larger machine";
}

std::string check_writable(const fs::path& out, const Scene& scene) {
  std::vector<fs::path> places{out};
  const auto& in = scene.instruments;
  if (in.hydrometer || in.buoyancy || in.pipette || scene.output.frames)
    places.push_back(out / "figures");
  if (scene.output.particles) places.push_back(out / "particles");
  if (scene.output.fields) places.push_back(out / "fields");
  if (scene.output.frames) places.push_back(out / "frames");
  if (in.hydrometer) places.push_back(out / "hydrometer");
  for (const auto& dir : places) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) return dir.string() + ": cannot create the folder: " + ec.message();
    const fs::path probe = dir / ".sedem-write-probe";
    errno = 0;
    FILE* f = std::fopen(probe.c_str(), "w");
    if (!f) return dir.string() + ": cannot write in it: " + std::strerror(errno);
    const bool ok = std::fputs("probe\n", f) >= 0;
    const bool closed = std::fclose(f) == 0;
    const int e = errno;
    fs::remove(probe, ec);
    if (!ok || !closed)
      return dir.string() + ": cannot write in it: " + (e ? std::strerror(e) : "write error");
  }
  return {};
}

void remove_temporary_files(const fs::path& out) {
  std::error_code ec;
  std::vector<fs::path> tmp;
  for (fs::recursive_directory_iterator it(out, ec), end; !ec && it != end; it.increment(ec))
    if (it->path().extension() == ".tmp") tmp.push_back(it->path());
  for (const auto& f : tmp) fs::remove(f, ec);
}

}  // namespace sedem::app
