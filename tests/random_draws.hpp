#pragma once
/// Random draws shared by the contact tests (test_relax_roots.cpp, test_cone_contact.cpp, the
/// polygon and mesh wall tests): scales spread over decades, directions, flights.
#include <cmath>

#include "core/relax_flight.hpp"
#include "core/rng.hpp"
#include "core/vec3.hpp"
#include "tests/test_constants.hpp"

namespace carom::test {

/// A number whose logarithm is uniform on [log lo, log hi).
inline double log_uniform(Rng& rng, double lo, double hi) {
  return std::exp(rng.uniform(std::log(lo), std::log(hi)));
}

/// A direction uniform on the unit sphere.
inline Vec3 unit(Rng& rng) {
  return rng.normal3().normalized();
}

/// Gravity alone (a ballistic flight) with probability `zero_rate_probability`; otherwise a
/// relax flight with rate 1..1e4 1/s (log-uniform) towards a terminal velocity of 0.01..10 m/s
/// in a random direction, under gravity.
inline RelaxFlight random_flight(Rng& rng, double zero_rate_probability) {
  if (rng.uniform() < zero_rate_probability) return {0.0, kGravityVector};
  const double rate = log_uniform(rng, 1.0, 1e4);
  return {rate, kGravityVector + rate * log_uniform(rng, 0.01, 10.0) * unit(rng)};
}

}  // namespace carom::test
