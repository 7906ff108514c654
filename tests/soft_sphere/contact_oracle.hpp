#pragma once
// A slow, plainly written reference for one Hertz–Mindlin impact with Coulomb friction, in the
// plane of the motion: x tangential, z normal, spins about +y. It shares no code with carom's
// soft-sphere method: its own constants (E*, G*, the damping for e found by its own bisection),
// its own contact geometry, and a step of the contact time / 1e5 or finer.
//
// The model is the one carom states (events/soft_sphere/contact_model.hpp), from the
// literature (Hertz; Mindlin's no-slip tangential stiffness; Tsuji-type damping in LIGGGHTS'
// form; Cundall & Strack's spring with a Coulomb cap):
//   F_n = k_n d^3/2 + c_n d^1/4 d',  k_n = 4/3 E* sqrt(R*),  c_n = 2 sqrt(5/6) b sqrt(2 E* sqrt(R*)
//   m*) F_t = -k_t sqrt(d) s - c_t d^1/4 g_t,  k_t = 8 G* sqrt(R*),  c_t = 2 sqrt(5/6) b sqrt(8 G*
//   sqrt(R*) m*) s' = g_t (the spring follows the contact point's slip), |F_t| <= mu max(F_n, 0):
//   beyond it F_t = mu max(F_n, 0) along the trial force, and s = -F_t / (k_t sqrt(d)),
// d the overlap, g_t the contact point's tangential velocity, lever arms the radii.
#include <algorithm>
#include <cmath>

namespace carom::soft_test {

/// Elastic constants of one material: E (Pa), nu.
struct OracleMaterial {
  double young = 0;
  double poisson = 0;
};

/// One body in the plane. mass = 0 marks the rigid plane z = 0 (never moves).
struct Body2D {
  double x = 0, z = 0;    ///< centre, m
  double vx = 0, vz = 0;  ///< velocity, m/s
  double spin = 0;    ///< about +y, rad/s (contact point of a sphere on the floor moves at -a w)
  double radius = 0;  ///< m
  double mass = 0;    ///< kg (0: the fixed plane)
  double inertia() const { return 0.4 * mass * radius * radius; }
};

/// The constants of one contact (see the header comment), SI units.
struct OracleContact {
  double k_n = 0, k_t = 0, c_n = 0, c_t = 0, mu = 0;
  double e_star = 0, g_star = 0, r_star = 0, m_star = 0;
};

/// Coefficient of restitution of a normal impact with damping factor b (v = 1 m/s; e does not
/// depend on the speed): RK4 with 2e4 steps per contact, the end interpolated linearly.
inline double oracle_restitution(const OracleContact& c, double b) {
  const double cn =
      2 * std::sqrt(5.0 / 6.0) * b * std::sqrt(2 * c.e_star * std::sqrt(c.r_star) * c.m_star);
  const double peak = std::pow(1.25 * c.m_star / c.k_n, 0.4);
  const double h = 2.9432752 * peak / 2e4;
  auto acc = [&](double d, double v) {
    const double dp = std::max(d, 0.0);
    return -(c.k_n * dp * std::sqrt(dp) + cn * std::sqrt(std::sqrt(dp)) * v) / c.m_star;
  };
  double d = 0, v = 1;
  for (int i = 0; i < 10'000'000; ++i) {
    const double a1 = acc(d, v), d2 = d + 0.5 * h * v, v2 = v + 0.5 * h * a1;
    const double a2 = acc(d2, v2), d3 = d + 0.5 * h * v2, v3 = v + 0.5 * h * a2;
    const double a3 = acc(d3, v3), d4 = d + h * v3, v4 = v + h * a3;
    const double a4 = acc(d4, v4);
    const double dn = d + h / 6 * (v + 2 * v2 + 2 * v3 + v4);
    const double vn = v + h / 6 * (a1 + 2 * a2 + 2 * a3 + a4);
    if (dn <= 0 && i > 0) return -(v + (vn - v) * d / (d - dn));
    d = dn;
    v = vn;
  }
  return 0;
}

/// The contact of sphere 1 (radius, mass, material a) with sphere 2 (or, mass2 = 0, with a
/// rigid plane of material b), restitution e and friction mu.
inline OracleContact oracle_contact(double radius1, double mass1, const OracleMaterial& a,
                                    double radius2, double mass2, const OracleMaterial& b, double e,
                                    double mu) {
  OracleContact c;
  c.e_star = 1 / ((1 - a.poisson * a.poisson) / a.young + (1 - b.poisson * b.poisson) / b.young);
  c.g_star = 1 / (2 * (2 - a.poisson) * (1 + a.poisson) / a.young +
                  2 * (2 - b.poisson) * (1 + b.poisson) / b.young);
  c.r_star = mass2 > 0 ? radius1 * radius2 / (radius1 + radius2) : radius1;
  c.m_star = mass2 > 0 ? mass1 * mass2 / (mass1 + mass2) : mass1;
  c.k_n = 4.0 / 3.0 * c.e_star * std::sqrt(c.r_star);
  c.k_t = 8 * c.g_star * std::sqrt(c.r_star);
  c.mu = mu;
  double beta = 0;
  if (e < 1) {  // e falls monotonically with b: bisection
    double lo = 0, hi = 1;
    while (oracle_restitution(c, hi) > e) hi *= 2;
    for (int k = 0; k < 40; ++k) {
      const double mid = 0.5 * (lo + hi);
      (oracle_restitution(c, mid) > e ? lo : hi) = mid;
    }
    beta = 0.5 * (lo + hi);
  }
  c.c_n =
      2 * std::sqrt(5.0 / 6.0) * beta * std::sqrt(2 * c.e_star * std::sqrt(c.r_star) * c.m_star);
  c.c_t =
      2 * std::sqrt(5.0 / 6.0) * beta * std::sqrt(8 * c.g_star * std::sqrt(c.r_star) * c.m_star);
  return c;
}

/// Hertz contact time at approach speed v (undamped), s.
inline double oracle_contact_time(const OracleContact& c, double v) {
  return 2.9432752 * std::pow(1.25 * c.m_star * v * v / c.k_n, 0.4) / v;
}

/// What the impact gave besides the bodies' final state.
struct OracleImpact {
  double repulsive_impulse = 0;  ///< int max(F_n, 0) dt, N s
  double normal_impulse = 0;     ///< int F_n dt, N s
};

/// Integrates the impact of b1 on b2 (b2.mass = 0: the plane z = 0) from first touch to
/// separation with velocity Verlet at `steps` steps per (undamped Hertz) contact time; b1
/// must start touching or just apart and approaching. Bodies are updated in place.
inline OracleImpact oracle_impact(Body2D& b1, Body2D& b2, const OracleContact& c, double steps) {
  OracleImpact out;
  const bool plane = b2.mass == 0;
  auto normal_speed = [&] {
    if (plane) return -b1.vz;
    const double dx = b1.x - b2.x, dz = b1.z - b2.z, r = std::hypot(dx, dz);
    return -((b1.vx - b2.vx) * dx + (b1.vz - b2.vz) * dz) / r;
  };
  const double h = oracle_contact_time(c, normal_speed()) / steps;
  double spring = 0;                        // s, along the tangent t
  double f1x = 0, f1z = 0, t1 = 0, t2 = 0;  // force on 1 (2 gets minus), torques about y
  bool touched = false;
  auto kick = [&] {
    b1.vx += 0.5 * h * f1x / b1.mass;
    b1.vz += 0.5 * h * f1z / b1.mass;
    b1.spin += 0.5 * h * t1 / b1.inertia();
    if (!plane) {
      b2.vx -= 0.5 * h * f1x / b2.mass;
      b2.vz -= 0.5 * h * f1z / b2.mass;
      b2.spin += 0.5 * h * t2 / b2.inertia();
    }
  };
  for (long i = 0; i < 100'000'000; ++i) {
    kick();
    b1.x += h * b1.vx;
    b1.z += h * b1.vz;
    if (!plane) {
      b2.x += h * b2.vx;
      b2.z += h * b2.vz;
    }
    // Normal n from 2 to 1, overlap d, tangent t = (n_z, -n_x).
    double nx = 0, nz = 1, d;
    if (plane) {
      d = b1.radius - b1.z;
    } else {
      const double dx = b1.x - b2.x, dz = b1.z - b2.z, r = std::hypot(dx, dz);
      nx = dx / r;
      nz = dz / r;
      d = b1.radius + b2.radius - r;
    }
    if (d <= 0) {
      f1x = f1z = t1 = t2 = 0;
      if (touched) break;
      continue;
    }
    touched = true;
    const double tx = nz, tz = -nx;
    // Contact point offsets r1 = -a1 n, r2 = +a2 n; a spin w about y moves an offset r at
    // (w r_z, -w r_x).
    const double r1x = -b1.radius * nx, r1z = -b1.radius * nz;
    const double r2x = b2.radius * nx, r2z = b2.radius * nz;
    double gx = b1.vx + b1.spin * r1z, gz = b1.vz - b1.spin * r1x;
    if (!plane) {
      gx -= b2.vx + b2.spin * r2z;
      gz -= b2.vz - b2.spin * r2x;
    }
    const double approach = -(gx * nx + gz * nz), g_t = gx * tx + gz * tz;
    const double root = std::sqrt(d), quarter = std::sqrt(root);
    const double f_n = c.k_n * d * root + c.c_n * quarter * approach;
    const double k_t = c.k_t * root;
    spring += h * g_t;
    double f_t = -k_t * spring - c.c_t * quarter * g_t;
    const double limit = c.mu * std::max(f_n, 0.0);
    if (std::abs(f_t) > limit) {
      f_t = f_t > 0 ? limit : -limit;
      spring = -f_t / k_t;
    }
    out.repulsive_impulse += h * std::max(f_n, 0.0);
    out.normal_impulse += h * f_n;
    f1x = f_n * nx + f_t * tx;
    f1z = f_n * nz + f_t * tz;
    t1 = r1z * f1x - r1x * f1z;     // (r1 x F)_y
    t2 = -(r2z * f1x - r2x * f1z);  // (r2 x -F)_y
    kick();
  }
  return out;
}

}  // namespace carom::soft_test
