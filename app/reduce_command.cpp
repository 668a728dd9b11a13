#include "app/reduce_command.h"

#include <cstdio>
#include <fstream>
#include <iostream>

#include "app/exit_codes.h"
#include "core/lab/hydrometer_reduction.h"
#include "core/lab/lab_csv.h"

namespace sedem::app {

int reduce(const ReduceOptions& options) {
  std::ifstream in(options.readings);
  if (!in) {
    std::fprintf(stderr, "sedem: %s: cannot open the readings file\n", options.readings.c_str());
    return exit_code::invalid_scene;
  }
  std::vector<LabPoint> points;
  try {
    const auto readings = read_lab_readings_csv(in);
    const LabSpecimen specimen{options.specific_gravity, options.dry_mass_g * 1e-3};
    points = options.method == "d7928" ? reduce_astm_d7928(readings, specimen)
                                       : reduce_astm_d422(readings, specimen);
  } catch (const std::invalid_argument& e) {  // LabCsvError, InvalidLabReading
    std::fprintf(stderr, "sedem: %s: %s\n", options.readings.c_str(), e.what());
    return exit_code::invalid_scene;
  }
  if (options.out.empty()) {
    write_lab_points_csv(std::cout, points);
    return std::cout ? exit_code::ok : exit_code::io_failure;
  }
  std::ofstream out(options.out);
  write_lab_points_csv(out, points);
  out.flush();
  if (!out) {
    std::fprintf(stderr, "sedem: cannot write %s\n", options.out.c_str());
    return exit_code::output_unwritable;
  }
  return exit_code::ok;
}

}  // namespace sedem::app
