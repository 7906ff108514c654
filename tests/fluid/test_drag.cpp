// Drag closures against tests/VALIDATION.md and hand calculations (fluid/drag.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <string>

#include "fluid/drag.hpp"
#include "tests/test_constants.hpp"

namespace carom {
namespace {

using carom::test::kPi;
using carom::test::kGravity;

/// 0.5 mm glass (2500 kg/m^3) in air (1.2 kg/m^3, 1.8e-5 Pa s): the tests/VALIDATION.md case.
DragInput glass_in_air(double eps = 1.0, double slip = 0.0) {
  DragInput in;
  in.porosity = eps;
  in.slip = slip;
  in.diameter = 0.5e-3;
  in.gas_density = 1.2;
  in.gas_viscosity = 1.8e-5;
  in.particle_density = 2500.0;
  return in;
}

double beta_of(DragClosureKind kind, double eps, double slip) {
  return DragClosure(kind).momentum_exchange(glass_in_air(eps, slip));
}

// tests/VALIDATION.md, "Drag closures": beta in kg/(m^3 s) at three (eps, slip) points. The table
// has 5 significant figures, so relative 1e-4 is its precision (a wrong exponent, Re
// definition or K <-> beta conversion is off by far more).
TEST(DragValidation, BetaTableErgunWenYuBlend) {
  struct Row {
    double eps, slip, ergun, wen_yu, blend;
  };
  const Row rows[] = {{0.4, 1.0, 1.2240e4, 1.6655e4, 1.2253e4},
                      {0.8, 0.1, 624.00, 605.99, 615.00},
                      {0.9, 1.0, 540.00, 437.25, 438.50}};
  for (const Row& r : rows) {
    SCOPED_TRACE("eps = " + std::to_string(r.eps) + ", slip = " + std::to_string(r.slip));
    EXPECT_NEAR(beta_of(DragClosureKind::Ergun, r.eps, r.slip) / r.ergun, 1.0, 1e-4);
    EXPECT_NEAR(beta_of(DragClosureKind::WenYu, r.eps, r.slip) / r.wen_yu, 1.0, 1e-4);
    EXPECT_NEAR(beta_of(DragClosureKind::GidaspowBlend, r.eps, r.slip) / r.blend, 1.0, 1e-4);
  }
}

// Single glass sphere settling in still air under Schiller-Naumann: 3.706 m/s, Re 123.5,
// C_d 0.9915 (tests/VALIDATION.md, "Settling and minimum fluidization", 4 significant figures:
// 0.05 % on the velocity).
TEST(DragSettling, SchillerNaumannTerminalVelocity) {
  const DragInput in = glass_in_air();
  const double ut = DragClosure(DragClosureKind::SchillerNaumann).terminal_velocity(in);
  EXPECT_NEAR(ut / 3.706, 1.0, 5e-4);
  const double re = in.gas_density * in.diameter * ut / in.gas_viscosity;
  EXPECT_NEAR(re / 123.5, 1.0, 5e-4);
  EXPECT_NEAR(schiller_naumann_cd(re) / 0.9915, 1.0, 5e-4);
  // The closed-form terminal Reynolds number agrees with the generic force-balance solver.
  const RichardsonZaki rz = richardson_zaki(in, 0.4, kGravity);
  EXPECT_NEAR(rz.terminal_velocity / ut, 1.0, 1e-12);
}

// Wen-Yu correlation: Ar = 1.1349e4, Re_mf = 6.284, U_mf = 0.1885 m/s (tests/VALIDATION.md,
// 4-5 significant figures).
TEST(DragFluidization, WenYuCorrelation) {
  const DragInput in = glass_in_air();
  const double ar = archimedes_number(in, kGravity);
  EXPECT_NEAR(ar / 1.1349e4, 1.0, 1e-4);
  EXPECT_NEAR(wen_yu_minimum_fluidization_reynolds(ar) / 6.284, 1.0, 1e-4);
  EXPECT_NEAR(wen_yu_minimum_fluidization_velocity(in, kGravity) / 0.1885, 1.0, 2e-4);
}

// The Schiller-Naumann closure's exponent n is chosen so that the closure itself fluidizes a
// bed at eps_mf exactly at the Wen-Yu U_mf (n = ln(Re_mf / Re_t) / ln eps_mf = 3.2507 here,
// from Re_mf = 6.28397, Re_t = 123.538), and expands like Richardson-Zaki U = U_t eps^n.
TEST(DragFluidization, SchillerNaumannReproducesWenYuAtEpsMf) {
  const DragInput in = glass_in_air();
  const DragClosure closure(DragClosureKind::SchillerNaumann, 0.4, kGravity);
  const RichardsonZaki rz = richardson_zaki(in, 0.4, kGravity);
  EXPECT_NEAR(rz.exponent, 3.25066, 1e-5);
  EXPECT_NEAR(rz.minimum_fluidization / 0.18852, 1.0, 1e-4);
  // Bisection to 1e-15: the closure and the correlation agree to round-off.
  EXPECT_NEAR(closure.minimum_fluidization_velocity(in, 0.4) / rz.minimum_fluidization, 1.0, 1e-10);
  for (double eps : {0.45, 0.6, 0.8, 0.95})
    EXPECT_NEAR(closure.minimum_fluidization_velocity(in, eps) /
                    (rz.terminal_velocity * std::pow(eps, rz.exponent)),
                1.0, 1e-10);
}

// The Ergun-based closures predict their own U_mf: with K u = eps V_p (rho_p - rho_g) g and
// u = U / eps, Ergun is the quadratic 150 (1-eps) mu U / (eps^3 d^2) + 1.75 rho_g U^2 / (eps^3 d)
// = (rho_p - rho_g) g (the Ergun pressure drop equals the buoyant weight per unit height).
TEST(DragFluidization, ErgunPressureDropBalancesBuoyantWeight) {
  const DragInput in = glass_in_air();
  const double eps = 0.4, d = in.diameter, mu = in.gas_viscosity, rho = in.gas_density;
  const double a = 1.75 * rho / (eps * eps * eps * d);
  const double b = 150.0 * (1.0 - eps) * mu / (eps * eps * eps * d * d);
  const double c = -(in.particle_density - rho) * kGravity;
  const double u_mf = (-b + std::sqrt(b * b - 4.0 * a * c)) / (2.0 * a);
  const DragClosure ergun(DragClosureKind::Ergun, 0.4, kGravity);
  EXPECT_NEAR(ergun.minimum_fluidization_velocity(in, eps) / u_mf, 1.0, 1e-10);
  // Below eps = 0.8 Gidaspow is Ergun; the blend differs from Ergun by phi ~ 1e-3 only.
  const DragClosure gidaspow(DragClosureKind::Gidaspow, 0.4, kGravity);
  EXPECT_NEAR(gidaspow.minimum_fluidization_velocity(in, eps) / u_mf, 1.0, 1e-10);
}

// The porosity exponents are the model-A ones: in the creeping-flow limit (1 um glass in air,
// Re ~ 1e-5) a bed's fluidization velocity scales as U ~ eps^n with the Richardson-Zaki n =
// 1 + 2.65 + 1 = 4.65 for Wen-Yu (K ~ eps^-2.65, K U / eps = eps W) and n = 1 + chi = 4.7 for
// Di Felice (chi -> 3.7). Written as a model-B force (drag plus pressure-gradient share), the
// same formulas would give n - 1. Tolerance 0.01: the residual Re dependence is ~1e-3.
TEST(DragFluidization, CreepingFlowExponentsAreRichardsonZaki) {
  DragInput in = glass_in_air();
  in.diameter = 1e-6;
  auto exponent = [&](DragClosureKind kind) {
    const DragClosure closure(kind, 0.4, kGravity);
    return std::log(closure.minimum_fluidization_velocity(in, 0.9) /
                    closure.minimum_fluidization_velocity(in, 0.5)) /
           std::log(0.9 / 0.5);
  };
  EXPECT_NEAR(exponent(DragClosureKind::WenYu), 4.65, 0.01);
  EXPECT_NEAR(exponent(DragClosureKind::DiFelice), 4.70, 0.01);
}

// Each closure at one point, computed by hand: d = 0.5 mm, rho_g = 1.2, mu = 1.8e-5,
// eps = 0.6, slip = 0.5 m/s, so Re = 0.6 * 1.2 * 5e-4 * 0.5 / 1.8e-5 = 10 exactly;
// V_p = pi (5e-4)^3 / 6 = 6.5450e-11 m^3, 3 pi mu d = 8.4823e-8 kg/s. Tolerance 1e-4: the
// hand values carry 5 figures.
TEST(DragClosures, HandComputedPoint) {
  const DragInput in = glass_in_air(0.6, 0.5);
  ASSERT_NEAR(reynolds_number(in), 10.0, 1e-12);
  auto k = [&](DragClosureKind kind) {
    return DragClosure(kind, 0.4, kGravity).drag_coefficient(in);
  };
  // Ergun: V_p [150 * 0.4 * 1.8e-5 / (0.6 * 2.5e-7) + 1.75 * 1.2 * 0.5 / 5e-4]
  //      = 6.5450e-11 * (7200 + 2100) = 6.0868e-7 kg/s.
  EXPECT_NEAR(k(DragClosureKind::Ergun) / 6.0868e-7, 1.0, 1e-4);
  // Gidaspow below eps = 0.8 is Ergun.
  EXPECT_NEAR(k(DragClosureKind::Gidaspow) / 6.0868e-7, 1.0, 1e-4);
  // Wen-Yu: 3 pi mu d eps^-2.65 (1 + 0.15 Re^0.687); 10^0.687 = 4.8641, 1 + 0.72961 = 1.72961,
  // 0.6^-2.65 = exp(2.65 * 0.510826) = 3.87164: 8.4823e-8 * 3.87164 * 1.72961 = 5.6802e-7.
  EXPECT_NEAR(k(DragClosureKind::WenYu) / 5.6802e-7, 1.0, 1e-4);
  // Blend: phi = 1/2 + atan(262.5 * (0.6 - 0.8)) / pi = 1/2 + atan(-52.5) / pi = 0.0060623;
  // 6.0868e-7 + 0.0060623 * (5.6802e-7 - 6.0868e-7) = 6.0844e-7.
  EXPECT_NEAR(k(DragClosureKind::GidaspowBlend) / 6.0844e-7, 1.0, 1e-4);
  // Schiller-Naumann + Richardson-Zaki, n = 3.25066: Re_f = 0.6^-3.25066 * 10 = 52.6205,
  // 52.6205^0.687 = 15.2207, factor 1 + 0.15 * 15.2207 = 3.28310;
  // eps^(2-n) = 0.6^-1.25066 = 1.89437: 8.4823e-8 * 1.89437 * 3.28310 = 5.2754e-7.
  EXPECT_NEAR(k(DragClosureKind::SchillerNaumann) / 5.2754e-7, 1.0, 1e-4);
  // Beetstra, phi = 0.4: 10 * 0.4 / 0.36 = 11.1111; 0.36 (1 + 1.5 sqrt(0.4)) = 0.701526;
  // inertial 0.413 * 10 / (24 * 0.36) = 0.478009 times (1/0.6 + 3 * 0.6 * 0.4 + 8.4 * 10^-0.343
  // = 6.199780) over (1 + 10^1.2 * 10^-1.3 = 1.794328): 1.651622. F = 13.46426;
  // K = 3 pi mu d eps F = 8.4823e-8 * 0.6 * 13.46426 = 6.8525e-7.
  EXPECT_NEAR(beetstra_monodisperse_f(0.4, 10.0), 13.46426, 1e-5);
  EXPECT_NEAR(k(DragClosureKind::Beetstra) / 6.8525e-7, 1.0, 1e-4);
  // Di Felice: chi = 3.7 - 0.65 exp(-(1.5 - 1)^2 / 2) = 3.126377;
  // C_d = (0.63 + 4.8 / sqrt(10))^2 = 4.613446;
  // K = C_d (pi d^2 / 8) rho_g eps^2 slip eps^-chi = 4.613446 * 9.8175e-8 * 1.2 * 0.36 * 0.5
  //   * 0.6^-3.126377 (= 4.9385) = 4.8313e-7.
  EXPECT_NEAR(di_felice_exponent(10.0), 3.126377, 1e-6);
  EXPECT_NEAR(k(DragClosureKind::DiFelice) / 4.8313e-7, 1.0, 1e-4);
}

// A single sphere (eps = 1): every closure built on a single-sphere law reduces to it, with no
// 1/(1 - eps) singularity, and beta vanishes.
TEST(DragClosures, SingleSphereLimit) {
  for (double slip : {0.0, 0.01, 1.0, 30.0}) {
    const DragInput in = glass_in_air(1.0, slip);
    const double re = in.gas_density * in.diameter * slip / in.gas_viscosity;
    const double stokes = 3.0 * kPi * in.gas_viscosity * in.diameter;
    const double sn = stokes * schiller_naumann_factor(re);
    EXPECT_NEAR(DragClosure(DragClosureKind::SchillerNaumann).drag_coefficient(in) / sn, 1.0,
                1e-14);
    EXPECT_NEAR(DragClosure(DragClosureKind::WenYu).drag_coefficient(in) / sn, 1.0, 1e-14);
    EXPECT_EQ(DragClosure(DragClosureKind::WenYu).momentum_exchange(in), 0.0);
  }
}

// The Lathouwers/Huilin blend is continuous: over steps of 1e-4 in eps it never moves by more
// than the steepest slopes allow (|d ln beta / d eps| < 60 for either closure up to eps = 0.95,
// plus the switch's 262.5 / pi), and across eps = 0.8 +- 1e-9 not at all, while the plain
// Gidaspow switch jumps there (by 18 / 624 = 3 % at slip 0.1: Ergun 624, Wen-Yu 606).
TEST(DragClosures, GidaspowBlendIsContinuous) {
  for (double slip : {0.01, 0.1, 1.0, 10.0}) {
    double previous = beta_of(DragClosureKind::GidaspowBlend, 0.3, slip);
    for (double eps = 0.3 + 1e-4; eps < 0.95; eps += 1e-4) {
      const double beta = beta_of(DragClosureKind::GidaspowBlend, eps, slip);
      const double jump_bound = 1e-4 * (262.5 / kPi + 60.0) *
                                std::max(beta_of(DragClosureKind::Ergun, eps - 1e-4, slip),
                                         beta_of(DragClosureKind::WenYu, eps - 1e-4, slip));
      EXPECT_LE(std::abs(beta - previous), jump_bound) << "eps " << eps << " slip " << slip;
      previous = beta;
    }
    const double below = beta_of(DragClosureKind::GidaspowBlend, 0.8 - 1e-9, slip);
    const double above = beta_of(DragClosureKind::GidaspowBlend, 0.8 + 1e-9, slip);
    EXPECT_NEAR(below / above, 1.0, 1e-6);
    EXPECT_GT(std::abs(beta_of(DragClosureKind::Gidaspow, 0.8 - 1e-9, slip) /
                           beta_of(DragClosureKind::Gidaspow, 0.8 + 1e-9, slip) -
                       1.0),
              1e-3);
  }
}

// Beetstra polydisperse correction: y = 1 is the monodisperse closure, and in a bidisperse bed
// the total drag equals that of a monodisperse bed of Sauter diameter (van der Hoef et al.
// 2005): sum_i n_i K_i = n K(<d>) with n_i = 6 phi_i / (pi d_i^3). Exact identities: 1e-12.
TEST(DragBeetstra, PolydisperseCorrection) {
  DragInput in = glass_in_air(0.55, 0.3);
  const double mono = beetstra_drag(in);
  in.sauter_diameter = in.diameter;
  EXPECT_NEAR(beetstra_drag(in) / mono, 1.0, 1e-14);

  const double eps = 0.55, phi = 1.0 - eps;
  const double d1 = 0.3e-3, d2 = 1.2e-3, phi1 = 0.15, phi2 = phi - phi1;
  const double sauter = phi / (phi1 / d1 + phi2 / d2);  // sum n d^3 / sum n d^2
  auto k = [&](double d) {
    DragInput p = glass_in_air(eps, 0.3);
    p.diameter = d;
    p.sauter_diameter = sauter;
    return beetstra_drag(p);
  };
  auto number_density = [](double fraction, double d) {
    return 6.0 * fraction / (kPi * d * d * d);
  };
  const double mixture = number_density(phi1, d1) * k(d1) + number_density(phi2, d2) * k(d2);
  const double monodisperse_bed = number_density(phi, sauter) * k(sauter);
  EXPECT_NEAR(mixture / monodisperse_bed, 1.0, 1e-12);

  // Model B check: drag plus the particle's share of the frictional pressure gradient,
  // K_i u + V_i (sum_j n_j K_j u) / eps, is 3 pi mu d_i U (F / eps)(eps y + phi y^2), the
  // van der Hoef / Beetstra total-force law.
  const double slip = 0.3, superficial = eps * slip;
  DragInput at_sauter = glass_in_air(eps, slip);
  at_sauter.diameter = sauter;
  const double re = reynolds_number(at_sauter);
  const double f = beetstra_monodisperse_f(phi, re);
  for (double d : {d1, d2}) {
    const double y = d / sauter;
    const double total = k(d) * slip + kPi * d * d * d / 6.0 * mixture * slip / eps;
    const double law = 3.0 * kPi * 1.8e-5 * d * superficial * f / eps * (eps * y + phi * y * y);
    EXPECT_NEAR(total / law, 1.0, 1e-12);
  }
}

// Every closure is positive and finite over eps in [0.35, 1] and Re in [1e-6, 1e4], and at
// zero slip.
TEST(DragClosures, PositiveAndFiniteEverywhere) {
  for (DragClosureKind kind :
       {DragClosureKind::SchillerNaumann, DragClosureKind::Ergun, DragClosureKind::WenYu,
        DragClosureKind::Gidaspow, DragClosureKind::GidaspowBlend, DragClosureKind::Beetstra,
        DragClosureKind::DiFelice}) {
    const DragClosure closure(kind);
    for (double eps = 0.35; eps <= 1.0 + 1e-12; eps += 0.01625) {
      for (double log_re = -6.0; log_re <= 4.0 + 1e-12; log_re += 0.25) {
        DragInput in = glass_in_air(std::min(eps, 1.0));
        in.slip = std::pow(10.0, log_re) * in.gas_viscosity /
                  (in.porosity * in.gas_density * in.diameter);
        for (double sauter : {0.0, 0.25e-3, 2e-3}) {
          in.sauter_diameter = sauter;
          const double k = closure.drag_coefficient(in);
          ASSERT_TRUE(std::isfinite(k) && k > 0.0)
              << drag_closure_name(kind) << " eps " << eps << " Re 1e" << log_re << " K " << k;
        }
      }
      DragInput at_rest = glass_in_air(std::min(eps, 1.0), 0.0);
      const double k = closure.drag_coefficient(at_rest);
      ASSERT_TRUE(std::isfinite(k) && k > 0.0) << drag_closure_name(kind) << " at rest";
    }
  }
}

// The closures as the formulas read, one expression each (drag.hpp's comments): the oracle of
// the factored path below. Written in the order the closures computed them before the factors
// of the porosity were kept, so that equal bits here mean the same runs as before.
double stokes(const DragInput& in) {
  return 3.0 * kPi * in.gas_viscosity * in.diameter;
}
double formula_wen_yu(const DragInput& in) {
  return stokes(in) * std::pow(in.porosity, -2.65) * schiller_naumann_factor(reynolds_number(in));
}
double formula_k(DragClosureKind kind, const DragInput& in) {
  const double eps = in.porosity;
  switch (kind) {
    case DragClosureKind::SchillerNaumann: {
      const double n = richardson_zaki(in, 0.4, kGravity).exponent;
      const double scaled_reynolds = std::pow(eps, -n) * reynolds_number(in);
      return stokes(in) * std::pow(eps, 2.0 - n) * schiller_naumann_factor(scaled_reynolds);
    }
    case DragClosureKind::WenYu:
      return formula_wen_yu(in);
    case DragClosureKind::Gidaspow:
      return eps < 0.8 ? ergun_drag(in) : formula_wen_yu(in);
    case DragClosureKind::GidaspowBlend: {
      const double phi = 0.5 + std::atan(262.5 * (eps - 0.8)) / kPi;
      return (1.0 - phi) * ergun_drag(in) + phi * formula_wen_yu(in);
    }
    case DragClosureKind::Beetstra: {
      const double mean_d = in.sauter_diameter > 0.0 ? in.sauter_diameter : in.diameter;
      const double re = eps * in.gas_density * mean_d * in.slip / in.gas_viscosity;
      const double phi = 1.0 - eps, e = 1.0 - phi;
      double f = 10.0 * phi / (e * e) + e * e * (1.0 + 1.5 * std::sqrt(phi));
      if (re > 0.0) {
        const double numerator = re / e + 3.0 * phi * e * re + 8.4 * std::pow(re, 0.657);
        const double denominator =
            1.0 + std::pow(10.0, 3.0 * phi) * std::pow(re, -0.5 * (1.0 + 4.0 * phi));
        f += 0.413 / (24.0 * e * e) * numerator / denominator;
      }
      return stokes(in) * eps * (in.diameter / mean_d) * f;
    }
    case DragClosureKind::Ergun:
      return ergun_drag(in);
    case DragClosureKind::DiFelice:
      return di_felice_drag(in);
    case DragClosureKind::MorsiAlexander:
      return DragClosure(kind).drag_coefficient(in);
  }
  return 0.0;
}

// The coupling takes each particle's porosity factors once a fluid step and its K twice, at two
// slips: K from factors taken at another slip is the formula's K at this one, bit for bit, for
// every closure, porosity (both sides of Gidaspow's switch), slip (0 included) and size ratio.
TEST(DragClosures, PorosityFactorsGiveTheFormulasBitForBit) {
  for (std::size_t k = 0; k < drag_closure_names().size(); ++k) {
    const auto kind = static_cast<DragClosureKind>(k);
    const DragClosure closure(kind, 0.4, kGravity);
    for (double eps : {0.36, 0.41, 0.55, 0.79999, 0.8, 0.83, 0.97, 1.0}) {
      for (double slip : {0.0, 1e-4, 0.03, 0.7, 4.0, 60.0}) {
        for (double sauter : {0.0, 0.3e-3, 1.7e-3}) {
          DragInput in = glass_in_air(eps, 2.5 * slip + 0.1);
          in.sauter_diameter = sauter;
          const PorosityFactors factors = closure.porosity_factors(in);
          in.slip = slip;
          const double expected = formula_k(kind, in);
          ASSERT_EQ(closure.drag_coefficient(in, factors), expected)
              << drag_closure_name(kind) << " eps " << eps << " slip " << slip;
          ASSERT_EQ(closure.drag_coefficient(in), expected) << drag_closure_name(kind);
        }
      }
    }
  }
}

TEST(DragClosures, NamesRoundTripAndBadNamesRejected) {
  for (std::string_view name : drag_closure_names())
    EXPECT_EQ(drag_closure_name(parse_drag_closure(name)), name);
  EXPECT_EQ(parse_drag_closure("wen-yu"), DragClosureKind::WenYu);
  for (const char* bad : {"", "stokes", "Ergun", "gidaspow blend", "beetstra2"}) {
    try {
      parse_drag_closure(bad);
      FAIL() << "accepted \"" << bad << "\"";
    } catch (const std::invalid_argument& e) {
      const std::string message = e.what();
      for (std::string_view name : drag_closure_names())
        EXPECT_NE(message.find(name), std::string::npos) << message;
    }
  }
  EXPECT_THROW(DragClosure(DragClosureKind::Ergun, 1.0), std::invalid_argument);  // eps_mf = 1
}

}  // namespace
}  // namespace carom
