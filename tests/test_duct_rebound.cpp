// The single-bead rebound of the convergent-duct study (Fohanno &
// Oesterle 2000): a 3 mm glass bead hits a glass wall at V1 = 3.5 m/s at the study's impact
// angles (from the wall) 17.6, 26.6, 40.04 and 57.8 degrees, without spin, in an event-driven
// run, under the static/kinetic Coulomb law with e = 0.96, mu_k = 0.12 and mu_s = 0.20
// (sliding walls) or 0.40 (non-sliding walls).
//
// Closed form (beta0 = 0): the normal velocity becomes -e v_n. The contact sticks when the
// tangential impulse that stops the slip, (2/7) m v_t, is at most mu_s (1 + e) m v_n, i.e. when
//   mu_s >= mu_T = 2 / (7 (1 + e) tan alpha1);
// then v_t' = (5/7) v_t; else it slides: v_t' = v_t - mu_k (1 + e) v_n. The rebound angle is
// alpha2 = atan(e v_n / v_t') and the tangential velocity ratio Psi = v_t' / v_t.
// mu_T is 0.460, 0.291, 0.174 and 0.092 at the four angles, so mu_s = 0.20 slides at the first
// two and sticks at the others, mu_s = 0.40 slides only at the first: both regimes and the
// threshold's two sides are covered. Tolerance 1e-12: one collision, exact algebra on O(1)
// numbers (the flight to the wall is straight and adds no error to the velocities).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>
#include <sstream>
#include <string>

#include "events/method_factory.hpp"
#include "scenarios/scene/scene.hpp"

namespace carom {
namespace {

struct Rebound {
  double angle = 0;  ///< alpha2, degrees.
  double ratio = 0;  ///< Psi = v_t' / v_t.
  bool sticks = false;
};

Rebound closed_form(double alpha1, double mu_s) {
  const double e = 0.96, mu_k = 0.12, v = 3.5;
  const double vn = v * std::sin(alpha1), vt = v * std::cos(alpha1);
  const bool sticks = mu_s >= 2.0 / (7.0 * (1.0 + e) * std::tan(alpha1));
  const double vt_after = sticks ? 5.0 / 7.0 * vt : vt - mu_k * (1.0 + e) * vn;
  return {std::atan2(e * vn, vt_after) * 180.0 / std::numbers::pi, vt_after / vt, sticks};
}

/// One bead at 2 cm from the x_low wall, flying at it; the run stops after the impact.
Rebound simulated(double alpha1, double mu_s) {
  const double v = 3.5, vn = v * std::sin(alpha1), vt = v * std::cos(alpha1);
  std::ostringstream text;
  text.precision(17);
  text << "[domain]\nmin = [0, 0, 0]\nmax = [0.1, 1.0, 0.1]\ngravity = [0, 0, 0]\n"
       << "[[species]]\nname = \"glass\"\ndiameter = 3.0e-3\ndensity = 2500.0\n"
       << "[[particles]]\nspecies = \"glass\"\nposition = [0.02, 0.05, 0.05]\nvelocity = [" << -vn
       << ", " << vt << ", 0.0]\n"
       << "[collisions]\ndefault = { e = 0.96, mu = 0.12, beta0 = 0.0 }\n"
       << "walls = { e = 0.96, mu = 0.12, mu_static = " << mu_s << ", beta0 = 0.0 }\n"
       << "[time]\nend = 1.0\n";
  Scene scene = parse_scene(text.str(), "rebound.toml");
  build_initial_state(scene);
  std::unique_ptr<CollisionMethod> sim = make_method(scene.system, scene.method);
  const double impact = (0.02 - 1.5e-3) / vn;
  sim->run_until(1.5 * impact);
  EXPECT_EQ(sim->statistics().wall_events, 1u);
  const Vec3 after = sim->velocity(0);
  return {std::atan2(after.x(), after.y()) * 180.0 / std::numbers::pi, after.y() / vt, false};
}

TEST(DuctRebound, SingleBeadAgainstStaticKineticCoulomb) {
  std::ostringstream table;
  table << "alpha1  mu_s  regime   alpha2 (deg)  Psi\n";
  for (double degrees : {17.6, 26.6, 40.04, 57.8})
    for (double mu_s : {0.20, 0.40}) {
      const double alpha1 = degrees * std::numbers::pi / 180.0;
      const Rebound exact = closed_form(alpha1, mu_s);
      const Rebound run = simulated(alpha1, mu_s);
      EXPECT_NEAR(run.angle, exact.angle, 1e-10) << degrees << " deg, mu_s " << mu_s;
      EXPECT_NEAR(run.ratio, exact.ratio, 1e-12) << degrees << " deg, mu_s " << mu_s;
      table << degrees << "  " << mu_s << "  " << (exact.sticks ? "sticks" : "slides") << "  "
            << run.angle << "  " << run.ratio << "\n";
    }
  std::cout << table.str();
}

}  // namespace
}  // namespace carom
