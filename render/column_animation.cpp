#include "render/column_animation.h"

#include <algorithm>
#include <cstdio>

#include "render/offscreen_view.h"

namespace sedem::render {

ColumnAnimation::ColumnAnimation(const std::filesystem::path& out_dir, const Cylinder& cylinder,
                                 Options options)
    : dir_(out_dir),
      cylinder_(cylinder),
      options_(std::move(options)),
      count_(options_.first_frame) {
  std::filesystem::create_directories(dir_ / "frames");
}

std::string ColumnAnimation::frame_name(int index) {
  char name[48];
  std::snprintf(name, sizeof name, "frames/column_%06d.png", index);
  return name;
}

std::filesystem::path ColumnAnimation::add(const ColumnState& state) {
  if (options_.full_scale_fraction <= 0) {
    const auto& b = state.band_mass_fraction;
    const double largest = b.empty() ? 0.0 : *std::max_element(b.begin(), b.end());
    options_.full_scale_fraction = largest > 0 ? 2.0 * largest : 1.0;
  }
  MassBandsFigure f;
  f.height = cylinder_.height;
  f.width = cylinder_.diameter;
  f.panel_width = options_.panel_width;
  f.panel_height = options_.panel_height;
  f.full_scale_fraction = options_.full_scale_fraction;
  f.samples = {{options_.label, {state}}};
  const auto file = dir_ / frame_name(count_++);
  write_png(render_mass_bands(f), file);
  return file;
}

std::filesystem::path ColumnAnimation::add(double time, const Particles& particles) {
  ColumnState state;
  state.time_s = time;
  state.band_mass_fraction =
      band_fractions_from_particles(particles, cylinder_.height, options_.bands);
  state.particles = discs_of(particles);
  return add(state);
}

}  // namespace sedem::render
