#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace sedem {

// A particle whose state blew up: NaN/Inf, a runaway speed, or an overlap deeper than the
// smaller grain. The engine throws this rather than carry a silent NaN.
struct Blowup {
  bool found = false;
  std::uint32_t particle = 0;  // index in the sample (Particles::id gives the user's id)
  std::string quantity;        // "position", "velocity", "speed", "overlap", ...
  double value = 0;

  void note(std::uint32_t p, const char* what, double v) {
    if (found) return;
    found = true;
    particle = p;
    quantity = what;
    value = v;
  }
};

class InstabilityError : public std::runtime_error {
 public:
  InstabilityError(std::uint32_t id, double time, std::string quantity, double value);
  std::uint32_t particle_id;
  double time;
  std::string quantity;
  double value;
};

}  // namespace sedem
