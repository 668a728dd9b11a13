#include "app/reduce_command.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "app/exit_codes.h"
#include "core/lab/hydrometer_reduction.h"
#include "core/lab/lab_csv.h"
#include "core/model/shortened.h"
#include "render/atomic_write.h"

namespace sedem::app {

namespace {

// The largest readings file read: a laboratory's CSV is a few kilobytes.
constexpr std::uintmax_t kMaxReadingsBytes = 16u << 20;

}  // namespace

int reduce(const ReduceOptions& options) {
  // --out is checked first: a folder, a pipe or a device (as root, renaming over /dev/full
  // would replace the device) is refused before anything is read or written.
  if (!options.out.empty())
    for (const std::string& file : {options.out, options.out + ".tmp"})
      if (const std::string why = unfit_output_file(file); !why.empty()) {
        std::fprintf(stderr, "sedem: %s\n", shortened(why).c_str());
        return exit_code::output_unwritable;
      }
  std::error_code ec;
  const auto status = std::filesystem::status(options.readings, ec);
  if (!ec && std::filesystem::exists(status) &&
      (!std::filesystem::is_regular_file(status) ||
       std::filesystem::file_size(options.readings, ec) > kMaxReadingsBytes)) {
    std::fprintf(stderr, "sedem: %s: not a readings file (a folder, a device or over 16 MB)\n",
                 shortened(options.readings).c_str());
    return exit_code::invalid_scene;
  }
  std::ifstream in(options.readings);
  if (!in) {
    std::fprintf(stderr, "sedem: %s: cannot open the readings file: %s\n",
                 shortened(options.readings).c_str(), std::strerror(errno));
    return exit_code::invalid_scene;
  }
  std::vector<LabPoint> points;
  try {
    const auto readings = read_lab_readings_csv(in);
    const LabSpecimen specimen{options.specific_gravity, options.dry_mass_g * 1e-3,
                               options.volume_ml * 1e-6};
    points = reduce_lab_readings(readings, specimen, parse_lab_method(options.method));
  } catch (const std::invalid_argument& e) {  // LabCsvError, InvalidLabReading
    std::fprintf(stderr, "sedem: %s: %s\n", shortened(options.readings).c_str(), e.what());
    return exit_code::invalid_scene;
  }
  for (const auto& p : points)
    if (p.percent_finer > 100)
      std::fprintf(stderr, "sedem: warning: percent finer %.1f %% at %.0f s is above 100 %%\n",
                   p.percent_finer, p.time);
  std::ostringstream text;
  write_lab_points_csv(text, points);
  if (options.out.empty()) {
    // Checked after a flush: a full disk or a closed pipe is an error, not a silent loss.
    errno = 0;
    std::cout << text.str();
    std::cout.flush();
    if (!std::cout || std::fflush(stdout) != 0) {
      std::fprintf(stderr, "sedem: cannot write the standard output: %s\n",
                   errno ? std::strerror(errno) : "write error");
      return exit_code::io_failure;
    }
    return exit_code::ok;
  }
  // Through a temporary file renamed into place: a failed write leaves no half file.
  const std::string tmp = options.out + ".tmp";
  FILE* f = std::fopen(tmp.c_str(), "w");
  if (!f) {
    std::fprintf(stderr, "sedem: cannot write %s: %s\n", shortened(options.out).c_str(),
                 std::strerror(errno));
    return exit_code::output_unwritable;
  }
  const std::string s = text.str();
  errno = 0;
  const bool written = std::fwrite(s.data(), 1, s.size(), f) == s.size();
  const int write_errno = errno;
  const bool closed = std::fclose(f) == 0;
  const int close_errno = errno;
  if (!written || !closed || std::rename(tmp.c_str(), options.out.c_str()) != 0) {
    const int e = !written ? write_errno : !closed ? close_errno : errno;
    std::fprintf(stderr, "sedem: cannot write %s: %s\n", shortened(options.out).c_str(),
                 e ? std::strerror(e) : "write error");
    std::remove(tmp.c_str());
    return exit_code::io_failure;
  }
  return exit_code::ok;
}

}  // namespace sedem::app
