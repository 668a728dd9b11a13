#include "app/output_observers.h"

#include <algorithm>
#include <cmath>

#include "core/fields/layer_fields.h"
#include "core/run/stage_setups.h"

namespace sedem::app {

namespace {

// Series entries strictly before a resumed run's start stay; the one at the start is
// written again by the resumed run.
double keep_before(double resume_from) {
  return std::nextafter(resume_from, -std::numeric_limits<double>::infinity());
}

}  // namespace

ParticleSeriesObserver::ParticleSeriesObserver(std::vector<double> times, const Scene& scene,
                                               const std::filesystem::path& out_dir,
                                               double resume_from)
    : times_(std::move(times)),
      writer_(out_dir, scene.sample.particle_density, keep_before(resume_from)) {}

namespace {

render::ColumnAnimation::Options animation_options(const Scene& scene, double resume_from,
                                                   bool partial) {
  render::ColumnAnimation::Options o;
  o.label = scene.name;
  if (partial) o.label += " (partial run)";
  o.panel_width = int(scene.output.frame_width);
  o.panel_height = int(scene.output.frame_height);
  // The suspension starts uniform, 1/bands of the mass in each band: black at twice that,
  // a scale that does not depend on which frame comes first.
  o.full_scale_fraction = 2.0 / o.bands;
  const auto times = every(scene.output.interval, scene.end_time);
  o.first_frame =
      int(std::count_if(times.begin(), times.end(), [&](double t) { return t < resume_from; }));
  return o;
}

}  // namespace

ColumnFrameObserver::ColumnFrameObserver(const Scene& scene, const std::filesystem::path& out_dir,
                                         double resume_from, bool partial)
    : times_(every(scene.output.interval, scene.end_time)),
      animation_(out_dir, scene.cylinder, animation_options(scene, resume_from, partial)) {}

FieldsObserver::FieldsObserver(const Scene& scene, const std::filesystem::path& out_dir,
                               double resume_from)
    : scene_(scene),
      times_(every(scene.output.interval, scene.end_time)),
      writer_(out_dir, keep_before(resume_from)) {}

void FieldsObserver::observe(double time, const Particles& particles) {
  const LayerFields f =
      compute_layer_fields(particles, scene_.cylinder, scene_.fluid, scene_.sample.particle_density,
                           std::size_t(scene_.instruments.layers));
  render::LayerFields out;
  out.time_s = time;
  out.column_height_m = scene_.cylinder.height;
  out.section_width_m = scene_.cylinder.diameter;
  out.particle_density_kg_m3 = scene_.sample.particle_density;
  out.fluid_density_kg_m3 = scene_.fluid.density;
  out.suspension_density_kg_m3 = f.density();
  out.concentration_kg_m3 = f.concentration();
  writer_.write(out);
}

ColumnFigureObserver::ColumnFigureObserver(const Scene& scene)
    : height_(scene.cylinder.height), times_(scene.output.fig11_times) {
  std::erase_if(times_, [&](double t) { return t > scene.end_time * (1 + 1e-12); });
}

void ColumnFigureObserver::observe(double time, const Particles& particles) {
  render::ColumnState state;
  state.time_s = time;
  state.band_mass_fraction = render::band_fractions_from_particles(particles, height_, 40);
  state.particles = render::discs_of(particles);
  states_.push_back(std::move(state));
}

std::filesystem::path replay_folder(const Scene& scene, const std::filesystem::path& out_dir) {
  return scene.output.particles ? out_dir : out_dir / "replay";
}

RunObservers make_observers(const Scene& scene, const Sample& sample,
                            const std::filesystem::path& out_dir, ObserverStart start) {
  RunObservers r;
  const auto& ins = scene.instruments;
  if (ins.hydrometer || ins.buoyancy || ins.pipette) {
    auto instruments = std::make_unique<InstrumentObserver>(test_setup(scene), sample);
    r.instruments = instruments.get();
    r.all.push_back(std::move(instruments));
  }
  if (scene.output.fields)
    r.all.push_back(std::make_unique<FieldsObserver>(scene, out_dir, start.resume_from));
  if (scene.output.frames) {
    r.all.push_back(
        std::make_unique<ColumnFrameObserver>(scene, out_dir, start.resume_from, start.partial));
    auto columns = std::make_unique<ColumnFigureObserver>(scene);
    r.columns = columns.get();
    r.all.push_back(std::move(columns));
  }
  if (start.write_particles) {
    // The snapshots that observers which accumulate read are saved: a resumed run replays
    // them, and `sedem render` recomputes everything from the particle series. Particle files
    // off, only those of observers without a state of their own go to replay/ (removed when
    // the run completes): the instruments keep theirs in the checkpoint.
    std::vector<std::vector<double>> lists;
    for (const auto& o : r.all)
      if (o->accumulates() && (scene.output.particles || !o->keeps_state()))
        lists.push_back(o->wanted_times());
    if (scene.output.particles) lists.push_back(every(scene.output.interval, scene.end_time));
    if (!lists.empty())
      r.all.push_back(std::make_unique<ParticleSeriesObserver>(
          merge_times(lists), scene, replay_folder(scene, out_dir), start.resume_from));
  }
  return r;
}

}  // namespace sedem::app
