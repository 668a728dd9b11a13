#pragma once

#include <cstdint>
#include <random>

namespace sedem {

// Seeded random numbers that are the same on every platform: std::mt19937_64 is specified
// bit for bit, while the standard distributions are not.
class RandomStream {
 public:
  explicit RandomStream(std::uint64_t seed) : engine_(seed) {}

  // Uniform in [0, 1), 53 random bits.
  double uniform() { return double(engine_() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  // Uniform in [0, n); the modulo bias is below n / 2^64.
  std::uint64_t below(std::uint64_t n) { return engine_() % n; }

 private:
  std::mt19937_64 engine_;
};

}  // namespace sedem
