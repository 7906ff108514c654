#pragma once
/// A seeded, reproducible random number generator (same seed -> same stream on any platform).
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>

#include "vec3.hpp"

namespace carom {

/// 64-bit Mersenne Twister with distributions written out here, so results do not depend on
/// the standard library's implementation of std::*_distribution.
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : engine_(seed) {}

  /// Uniform in [0, 1).
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  /// Uniform in [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  /// Standard normal deviate (Box-Muller, both values used).
  double normal() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    double u1 = 0.0;
    while (u1 <= 0.0) u1 = uniform();
    const double u2 = uniform();
    const double radius = std::sqrt(-2.0 * std::log(u1));
    spare_ = radius * std::sin(2.0 * std::numbers::pi * u2);
    has_spare_ = true;
    return radius * std::cos(2.0 * std::numbers::pi * u2);
  }
  /// Three independent standard normal deviates.
  Vec3 normal3() {
    const double x = normal(), y = normal(), z = normal();
    return {x, y, z};
  }
  /// Uniform integer in [0, n).
  std::uint64_t below(std::uint64_t n) { return static_cast<std::uint64_t>(uniform() * n); }

  /// The complete state as text (the engine's standard textual state, then the spare normal
  /// deviate as its exact bits), for checkpoints: set_state(state()) continues the same stream.
  std::string state() const {
    std::ostringstream out;
    out << engine_ << ' ' << (has_spare_ ? 1 : 0) << ' ' << std::bit_cast<std::uint64_t>(spare_);
    return out.str();
  }
  /// Restores what state() wrote. Throws std::invalid_argument when `text` is not such a state.
  void set_state(const std::string& text) {
    std::istringstream in(text);
    int spare_flag = 0;
    std::uint64_t spare_bits = 0;
    in >> engine_ >> spare_flag >> spare_bits;
    if (!in || (spare_flag != 0 && spare_flag != 1))
      throw std::invalid_argument("not a random generator state");
    has_spare_ = spare_flag == 1;
    spare_ = std::bit_cast<double>(spare_bits);
  }

 private:
  std::mt19937_64 engine_;
  double spare_ = 0.0;
  bool has_spare_ = false;
};

}  // namespace carom
