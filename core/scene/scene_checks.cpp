#include "core/scene/scene_checks.h"

#include "core/scene/scene.h"
#include "core/scene/scene_loader.h"

namespace sedem {

void check_scene(const Scene& scene, const std::string& source) {
  auto fail = [&](const std::string& what) { throw SceneError(source + ": " + what); };
  if (scene.sample.particle_density <= scene.fluid.density)
    fail("sample.particle_density must exceed fluid.density, or nothing settles");
  const auto& g = scene.sample.grading;
  if (g.family == "table") {
    if (g.diameters.size() < 2 || g.diameters.size() != g.percent_finer.size())
      fail(
          "sample.grading.diameters_um and sample.grading.percent_finer must be lists of the "
          "same length, at least 2");
    for (std::size_t i = 1; i < g.diameters.size(); ++i) {
      if (!(g.diameters[i] > g.diameters[i - 1]))
        fail("sample.grading.diameters_um must be strictly ascending");
      if (g.percent_finer[i] < g.percent_finer[i - 1])
        fail("sample.grading.percent_finer must not decrease");
    }
    if (g.percent_finer.back() != 100.0) fail("sample.grading.percent_finer must end at 100");
  } else if (!(g.min_diameter < g.max_diameter)) {
    fail("sample.grading.min_um must be smaller than sample.grading.max_um");
  }
}

}  // namespace sedem
