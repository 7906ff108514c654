// The kick scheme (fluid/kick_scheme.hpp): one kick is the explicit Euler step of the drag and
// pressure-gradient acceleration, the scheme is first order in dt_p, and dt_p > 2 tau is refused
// before any velocity changes, with a message that names the particle and the remedies.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "fluid/kick_scheme.hpp"
#include "tests/test_constants.hpp"

namespace carom {
namespace {

using carom::test::kGravityVector;

/// One 1 mm bead with drag rate 1/tau towards the gas velocity u and a pressure-gradient
/// acceleration -grad p / rho_p = b: drive = g + rate u + b (core/relax_flight.hpp).
struct Bead {
  ParticleStore particles;
  std::vector<RelaxFlight> flights;
  Bead(double rate, const Vec3& u, const Vec3& b, const Vec3& v0) {
    particles.add(Vec3::Zero(), v0, Vec3::Zero(), 5e-4, 1.3e-6, 1.3e-13, 0, 42);
    flights.push_back(RelaxFlight{rate, kGravityVector + rate * u + b});
  }
};

// v' = v + dt_p [(u - v) / tau + b]: gravity is the ballistic flight's, not the kick's. Exact
// to round-off of the few operations (relative 1e-15).
TEST(KickScheme, OneKickIsTheExplicitDragAndPressureImpulse) {
  const double rate = 20.0, dt = 0.01;
  const Vec3 u(0.3, -0.1, 1.2), b(0.0, 0.0, 2.0), v0(0.05, 0.02, -0.4);
  Bead bead(rate, u, b, v0);
  KickScheme(dt, kGravityVector).kick(bead.particles, bead.flights);
  const Vec3 expected = v0 + dt * (rate * (u - v0) + b);
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(bead.particles.velocity[0][k], expected[k], 1e-15 * expected.norm()) << k;
}

// Against the exact relaxation v - u = (v0 - u) e^(-t / tau) over one tau: the kick gives
// (1 - dt_p / tau)^(tau / dt_p), whose error halves with dt_p (first order: 0.0192 at tau / 10,
// 0.0094 at tau / 20, a ratio of 2.04).
TEST(KickScheme, IsFirstOrderInTheParticleStep) {
  const double tau = 0.1;
  auto error_after_tau = [&](int kicks) {
    Bead bead(1.0 / tau, Vec3(1, 0, 0), Vec3::Zero(), Vec3::Zero());
    const KickScheme scheme(tau / kicks, kGravityVector);
    for (int n = 0; n < kicks; ++n) scheme.kick(bead.particles, bead.flights);
    return std::abs(bead.particles.velocity[0].x() - (1.0 - std::exp(-1.0)));
  };
  const double coarse = error_after_tau(10), fine = error_after_tau(20);
  EXPECT_NEAR(coarse, 0.0192, 1e-4);
  EXPECT_NEAR(coarse / fine, 2.04, 0.01);
}

// The limit: dt_p = 2 tau is the last stable step (each kick flips v - u without growth); beyond
// it the scheme throws before touching any velocity, naming the particle, the limit and the
// remedies.
TEST(KickScheme, RefusesStepsBeyondTwiceTheRelaxationTime) {
  const double rate = 4.0;  // tau = 0.25 s
  const Vec3 v0(0, 0, -1);
  Bead at_limit(rate, Vec3::Zero(), Vec3::Zero(), v0);
  EXPECT_NO_THROW(KickScheme(0.5, kGravityVector).kick(at_limit.particles, at_limit.flights));
  EXPECT_DOUBLE_EQ(at_limit.particles.velocity[0].z(), 1.0);  // v - u flipped: 1 - dt / tau = -1.

  Bead beyond(rate, Vec3::Zero(), Vec3::Zero(), v0);
  try {
    KickScheme(0.5000001, kGravityVector).kick(beyond.particles, beyond.flights);
    FAIL() << "dt_p > 2 tau must be refused";
  } catch (const KickUnstable& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("particle 42"), std::string::npos) << message;
    EXPECT_NE(message.find("2 tau"), std::string::npos) << message;
    EXPECT_NE(message.find("relax"), std::string::npos) << message;
    EXPECT_NE(message.find("particle_step"), std::string::npos) << message;
  }
  EXPECT_EQ(beyond.particles.velocity[0], v0);
  EXPECT_THROW(KickScheme(0.6, kGravityVector).check_stability(beyond.particles, beyond.flights), KickUnstable);
}

// With the longitudinal drag rate (1/m) dF/ds (GasCoupling::longitudinal_rates; larger than the
// secant rate K/m for a drag growing faster than the slip) the limit is 2 / that rate: here
// 2 / 6 = 1/3 s, below 2 tau = 0.5 s. At the limit the kick passes; just beyond it is refused
// with the largest stable step named; the same step passes the secant check alone.
TEST(KickScheme, LongitudinalRateLowersTheLimitBelowTwiceTau) {
  const std::vector<double> longitudinal{6.0};
  Bead bead(4.0, Vec3::Zero(), Vec3::Zero(), Vec3(0, 0, -1));
  EXPECT_NO_THROW(
      KickScheme(1.0 / 3.0, kGravityVector).check_stability(bead.particles, bead.flights, &longitudinal));
  EXPECT_NO_THROW(KickScheme(0.34, kGravityVector).check_stability(bead.particles, bead.flights));
  try {
    KickScheme(0.34, kGravityVector).check_stability(bead.particles, bead.flights, &longitudinal);
    FAIL() << "dt_p > 2 m/(dF/ds) must be refused";
  } catch (const KickUnstable& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("largest stable step 0.3333 s"), std::string::npos) << message;
    EXPECT_NE(message.find("dF/ds = 6 1/s"), std::string::npos) << message;
    EXPECT_NE(message.find("tau = m/K = 0.25 s"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace carom
