#pragma once

#include <filesystem>
#include <vector>

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include "render/field_writer.h"

namespace sedem::render {

// The hydrometer's outline as a radius profile, from its tip up: radius_m[i] at height_m[i]
// above the tip (increasing heights). A zero radius closes the surface at that end.
struct BulbProfile {
  std::vector<double> height_m;
  std::vector<double> radius_m;
};

enum class BulbPart {
  whole,
  // The half behind the section's plane (z <= 0) and the outline in that plane (a closed
  // line): seen from the particles' side it never hides them.
  back_half,
};

// The surface of revolution of `profile` about the cylinder's axis (x = 0, z = 0) with its
// tip at y = tip_y (y up, bottom of the column at 0), `segments` facets around (half of them
// for the back half); ends with a non-zero radius are capped. Quads and triangles,
// outward-facing.
vtkSmartPointer<vtkPolyData> bulb_surface(const BulbProfile& profile, double tip_y,
                                          int segments = 48, BulbPart part = BulbPart::whole);

// DIR/hydrometer.pvd and DIR/hydrometer/hydrometer_NNNNNN.vtp: the bulb at its equilibrium
// position at each reading, as its back half and outline (BulbPart::back_half), so that
// ParaView's default view shows the particles in front of it. Field data TimeValue and
// tip_depth (m below the free surface).
class HydrometerSeriesWriter {
 public:
  HydrometerSeriesWriter(const std::filesystem::path& out_dir, BulbProfile profile,
                         double column_height_m);
  std::filesystem::path write(double time_s, double tip_depth_m);

 private:
  XmlSeriesWriter series_;
  BulbProfile profile_;
  double height_;
};

}  // namespace sedem::render
