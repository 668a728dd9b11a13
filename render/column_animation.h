#pragma once

#include <filesystem>
#include <string>

#include "core/model/cylinder.h"
#include "core/model/particles.h"
#include "render/mass_bands.h"

namespace sedem::render {

// The column over time as a numbered PNG sequence, DIR/frames/column_000000.png, ...: each
// frame is one Fig. 11 panel (mass bands and zoom insets) of one sample. The grey scale is
// fixed for the whole sequence so that frames compare: unless `full_scale_fraction` is set,
// black is twice the largest band share of the first frame (larger shares stay black).
class ColumnAnimation {
 public:
  struct Options {
    std::string label = "column";
    int panel_width = 300;
    int panel_height = 560;
    int bands = 40;  // the paper's 4000 layers in bands of 100
    double full_scale_fraction = 0;
    int first_frame = 0;  // number of the first frame written (a resumed run goes on)
  };

  ColumnAnimation(const std::filesystem::path& out_dir, const Cylinder& cylinder, Options options);

  // Renders one frame from the state given; returns the file written.
  std::filesystem::path add(const ColumnState& state);
  // The same from the particles: bands from their weighted masses.
  std::filesystem::path add(double time, const Particles& particles);

  int frame_count() const { return count_; }
  static std::string frame_name(int index);  // "frames/column_000012.png"

 private:
  std::filesystem::path dir_;
  Cylinder cylinder_;
  Options options_;
  int count_ = 0;
};

}  // namespace sedem::render
