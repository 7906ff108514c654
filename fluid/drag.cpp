#include "drag.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "morsi_alexander.hpp"

namespace carom {

namespace {

/// The Stokes drag 3 pi mu d of a sphere, kg/s.
double stokes_coefficient(const DragInput& in) {
  return 3.0 * std::numbers::pi * in.gas_viscosity * in.diameter;
}

/// Solves f(U) = 0 for U > 0 by bisection in log U; f increasing, f(0+) < 0. `guess` > 0.
template <class Function>
double solve_increasing(Function f, double guess) {
  double lo = guess, hi = guess;
  for (int i = 0; i < 2000 && f(hi) < 0.0; ++i) hi *= 2.0;
  for (int i = 0; i < 2000 && f(lo) > 0.0; ++i) lo *= 0.5;
  for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) < 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}
}  // namespace

const std::array<std::string_view, 8>& drag_closure_names() {
  static const std::array<std::string_view, 8> names{
      "schiller_naumann", "ergun",     "wen_yu",         "gidaspow",
      "gidaspow_blend",   "beetstra",  "di_felice",      "morsi_alexander"};
  return names;
}

std::string_view drag_closure_name(DragClosureKind kind) {
  return drag_closure_names()[static_cast<std::size_t>(kind)];
}

DragClosureKind parse_drag_closure(std::string_view name) {
  std::string key(name);
  std::replace(key.begin(), key.end(), '-', '_');  // "wen-yu" reads as "wen_yu"
  const auto& names = drag_closure_names();
  for (std::size_t i = 0; i < names.size(); ++i)
    if (key == names[i]) return static_cast<DragClosureKind>(i);
  std::string message = "unknown drag closure \"" + std::string(name) + "\"; allowed: ";
  for (std::size_t i = 0; i < names.size(); ++i) message += (i ? ", " : "") + std::string(names[i]);
  throw std::invalid_argument(message);
}

double reynolds_number(const DragInput& in) {
  return in.porosity * in.gas_density * in.diameter * in.slip / in.gas_viscosity;
}

double particle_volume(double diameter) {
  return std::numbers::pi / 6.0 * diameter * diameter * diameter;
}

double schiller_naumann_factor(double reynolds) {
  if (reynolds < 1000.0) return 1.0 + 0.15 * std::pow(reynolds, 0.687);
  return 0.44 * reynolds / 24.0;
}

double schiller_naumann_cd(double reynolds) {
  return 24.0 / reynolds * schiller_naumann_factor(reynolds);
}

namespace {
// Each closure with factors of the porosity alone, as K from those factors (PorosityFactors):
// the free functions below and DragClosure take K through these, so both give the same bits.

/// Richardson-Zaki: the slip's factor eps^-n and the prefactor eps^(2 - n).
double schiller_naumann_with(const DragInput& in, double slip_factor, double prefactor) {
  const double scaled_reynolds = slip_factor * reynolds_number(in);
  return stokes_coefficient(in) * prefactor * schiller_naumann_factor(scaled_reynolds);
}

/// Wen-Yu's voidage function eps^-2.65.
double wen_yu_voidage(double porosity) {
  return std::pow(porosity, -2.65);
}

double wen_yu_with(const DragInput& in, double voidage) {
  return stokes_coefficient(in) * voidage * schiller_naumann_factor(reynolds_number(in));
}

double gidaspow_with(const DragInput& in, double voidage) {
  return in.porosity < 0.8 ? ergun_drag(in) : wen_yu_with(in, voidage);
}

double gidaspow_blend_with(const DragInput& in, double weight, double voidage) {
  return (1.0 - weight) * ergun_drag(in) + weight * wen_yu_with(in, voidage);
}

/// Beetstra's viscous part 10 phi / eps^2 + eps^2 (1 + 1.5 sqrt(phi)) (eps = 1 - phi).
double beetstra_viscous(double solid_fraction) {
  const double phi = solid_fraction, eps = 1.0 - phi;
  return 10.0 * phi / (eps * eps) + eps * eps * (1.0 + 1.5 * std::sqrt(phi));
}

/// Beetstra's F from its viscous part and 10^(3 phi).
double beetstra_f_with(double solid_fraction, double reynolds, double viscous, double ten_power) {
  const double phi = solid_fraction, eps = 1.0 - phi;
  if (reynolds <= 0.0) return viscous;
  // Inertial part, written so that Re -> 0 gives 0 without inf / inf.
  const double numerator =
      reynolds / eps + 3.0 * phi * eps * reynolds + 8.4 * std::pow(reynolds, 0.657);
  const double denominator = 1.0 + ten_power * std::pow(reynolds, -0.5 * (1.0 + 4.0 * phi));
  return viscous + 0.413 / (24.0 * eps * eps) * numerator / denominator;
}

double beetstra_with(const DragInput& in, double viscous, double ten_power) {
  const double mean_d = in.sauter_diameter > 0.0 ? in.sauter_diameter : in.diameter;
  const double y = in.diameter / mean_d;
  const double eps = in.porosity;
  const double mean_reynolds = eps * in.gas_density * mean_d * in.slip / in.gas_viscosity;
  return stokes_coefficient(in) * eps * y *
         beetstra_f_with(1.0 - eps, mean_reynolds, viscous, ten_power);
}
}  // namespace

double schiller_naumann_drag(const DragInput& in, double exponent_n) {
  const double eps = in.porosity;
  return schiller_naumann_with(in, std::pow(eps, -exponent_n), std::pow(eps, 2.0 - exponent_n));
}

double ergun_drag(const DragInput& in) {
  const double eps = in.porosity, d = in.diameter;
  return particle_volume(d) * (150.0 * (1.0 - eps) * in.gas_viscosity / (eps * d * d) +
                               1.75 * in.gas_density * in.slip / d);
}

double wen_yu_drag(const DragInput& in) {
  return wen_yu_with(in, wen_yu_voidage(in.porosity));
}

double gidaspow_drag(const DragInput& in) {
  return gidaspow_with(in, in.porosity < 0.8 ? 0.0 : wen_yu_voidage(in.porosity));
}

double gidaspow_blend_weight(double porosity) {
  return 0.5 + std::atan(262.5 * (porosity - 0.8)) / std::numbers::pi;
}

double gidaspow_blend_drag(const DragInput& in) {
  return gidaspow_blend_with(in, gidaspow_blend_weight(in.porosity), wen_yu_voidage(in.porosity));
}

double beetstra_monodisperse_f(double solid_fraction, double reynolds) {
  // Low-Re part (van der Hoef et al. 2005 in the Beetstra normalisation, eq. 16 first terms),
  // then the inertial part.
  return beetstra_f_with(solid_fraction, reynolds, beetstra_viscous(solid_fraction),
                         std::pow(10.0, 3.0 * solid_fraction));
}

// Polydisperse Beetstra in model A. Beetstra et al. (2007, with the erratum AIChE J. 53:3020)
// give the total fluid force on particle i (drag plus its share of the mean pressure gradient,
// "model B") as F_i^B / (3 pi mu d_i U) = (F / eps) (eps y_i + phi y_i^2 [+ 0.064 eps y_i^3]),
// F = F(phi, <Re>), y_i = d_i / <d>. The pressure-gradient share of particle i is
// V_i (-grad p) with -grad p = (sum_j n_j F_j^A) / eps; for F_j^A = 3 pi mu d_j U F y_j that sum is
// 18 mu U F phi / <d>^2 (Sauter mean: sum_j phi_j / d_j = phi / <d>), so the share is
// 3 pi mu d_i U F phi y_i^2 / eps and F_i^A + share = 3 pi mu d_i U (F / eps)(eps y_i + phi y_i^2):
// the model-A drag F_i^A = 3 pi mu d_i U F y_i reproduces the bidisperse law exactly. The
// 0.064 eps y^3 term of the finite-Re fit has no exact model-A counterpart and is left out, as
// in MFiX's model-A implementation; with it the law would not reduce to the monodisperse
// closure at y = 1 (it gives 1 + 0.064 eps there).
double beetstra_drag(const DragInput& in) {
  const double phi = 1.0 - in.porosity;
  return beetstra_with(in, beetstra_viscous(phi), std::pow(10.0, 3.0 * phi));
}

double di_felice_exponent(double reynolds) {
  if (reynolds <= 0.0) return 3.7;
  const double x = 1.5 - std::log10(reynolds);
  return 3.7 - 0.65 * std::exp(-0.5 * x * x);
}

double di_felice_drag(const DragInput& in) {
  const double re = reynolds_number(in);
  const double root = 0.63 * std::sqrt(re) + 4.8;
  return stokes_coefficient(in) * std::pow(in.porosity, 1.0 - di_felice_exponent(re)) * root *
         root / 24.0;
}

double archimedes_number(const DragInput& in, double gravity) {
  const double d = in.diameter, mu = in.gas_viscosity;
  return d * d * d * in.gas_density * (in.particle_density - in.gas_density) * gravity / (mu * mu);
}

double wen_yu_minimum_fluidization_reynolds(double archimedes) {
  // sqrt(a^2 + x) - a = x / (sqrt(a^2 + x) + a): no cancellation for small Ar.
  const double a = 33.7, x = 0.0408 * archimedes;
  return x / (std::sqrt(a * a + x) + a);
}

double wen_yu_minimum_fluidization_velocity(const DragInput& in, double gravity) {
  return wen_yu_minimum_fluidization_reynolds(archimedes_number(in, gravity)) * in.gas_viscosity /
         (in.gas_density * in.diameter);
}

double schiller_naumann_terminal_reynolds(double archimedes) {
  // C_d Re^2 = 24 Re (1 + 0.15 Re^0.687) below Re = 1000, 0.44 Re^2 above.
  const double target = 4.0 / 3.0 * archimedes;
  if (target <= 0.0) return 0.0;
  if (target >= 0.44e6) return std::sqrt(target / 0.44);
  const double at_1000 = 24.0e3 * schiller_naumann_factor(1000.0 - 1e-9);
  if (target >= at_1000) return 1000.0;  // inside the small jump of C_d at Re = 1000
  // Newton from the Stokes estimate, which lies above the root; h is convex, so the iterates
  // decrease monotonically to it.
  double re = std::min(target / 24.0, 1000.0);
  for (int i = 0; i < 100; ++i) {
    const double power = std::pow(re, 0.687);
    const double h = 24.0 * re + 3.6 * re * power - target;
    const double slope = 24.0 + 3.6 * 1.687 * power;
    const double step = h / slope;
    re -= step;
    if (std::abs(step) <= 1e-15 * re) break;
  }
  return re;
}

RichardsonZaki richardson_zaki(const DragInput& in, double fluidization_porosity, double gravity) {
  const double ar = archimedes_number(in, gravity);
  const double velocity_scale = in.gas_viscosity / (in.gas_density * in.diameter);
  RichardsonZaki rz;
  const double re_t = schiller_naumann_terminal_reynolds(ar);
  const double re_mf = wen_yu_minimum_fluidization_reynolds(ar);
  rz.terminal_velocity = re_t * velocity_scale;
  rz.minimum_fluidization = re_mf * velocity_scale;
  // Ar -> 0: Re_mf -> 0.0408 Ar / 67.4 and Re_t -> Ar / 18; use that ratio (n ~ 4.93).
  const double ratio = ar > 1e-12 ? re_mf / re_t : 0.0408 * 18.0 / (2.0 * 33.7);
  rz.exponent = std::log(ratio) / std::log(fluidization_porosity);
  return rz;
}

DragClosure::DragClosure(DragClosureKind kind, double fluidization_porosity, double gravity)
    : kind_(kind), fluidization_porosity_(fluidization_porosity), gravity_(gravity) {
  if (!(fluidization_porosity > 0.0 && fluidization_porosity < 1.0))
    throw std::invalid_argument("drag closure: the minimum-fluidization porosity eps_mf = " +
                                std::to_string(fluidization_porosity) +
                                " must lie strictly between 0 and 1 (typically 0.4 to 0.5)");
}

double DragClosure::richardson_zaki_exponent(const DragInput& in) const {
  // n depends only on the particle and gas properties: remember the last one per thread (a
  // Newton solve for Re_t costs ~0.3 us; consecutive particles usually share species).
  struct Memo {
    double diameter = -1, particle_density = 0, gas_density = 0, gas_viscosity = 0;
    double fluidization_porosity = 0, gravity = 0, exponent = 0;
  };
  thread_local Memo memo;
  if (memo.diameter != in.diameter || memo.particle_density != in.particle_density ||
      memo.gas_density != in.gas_density || memo.gas_viscosity != in.gas_viscosity ||
      memo.fluidization_porosity != fluidization_porosity_ || memo.gravity != gravity_) {
    memo = Memo{in.diameter,
                in.particle_density,
                in.gas_density,
                in.gas_viscosity,
                fluidization_porosity_,
                gravity_,
                richardson_zaki(in, fluidization_porosity_, gravity_).exponent};
  }
  return memo.exponent;
}

double DragClosure::drag_coefficient(const DragInput& in) const {
  return drag_coefficient(in, porosity_factors(in));
}

// What each closure keeps in PorosityFactors (first, second):
//   schiller_naumann  eps^-n, eps^(2 - n)      gidaspow (eps >= 0.8)  eps^-2.65, 0
//   wen_yu            eps^-2.65, 0             gidaspow_blend         the weight phi, eps^-2.65
//   beetstra          its viscous part, 10^(3 (1 - eps))
// Ergun, Di Felice (its exponent depends on Re) and Morsi-Alexander have none.
PorosityFactors DragClosure::porosity_factors(const DragInput& in) const {
  const double eps = in.porosity;
  switch (kind_) {
    case DragClosureKind::SchillerNaumann: {
      const double n = richardson_zaki_exponent(in);
      return {eps, std::pow(eps, -n), std::pow(eps, 2.0 - n)};
    }
    case DragClosureKind::WenYu:
      return {eps, wen_yu_voidage(eps), 0.0};
    case DragClosureKind::Gidaspow:
      return {eps, eps < 0.8 ? 0.0 : wen_yu_voidage(eps), 0.0};
    case DragClosureKind::GidaspowBlend:
      return {eps, gidaspow_blend_weight(eps), wen_yu_voidage(eps)};
    case DragClosureKind::Beetstra: {
      const double phi = 1.0 - eps;
      return {eps, beetstra_viscous(phi), std::pow(10.0, 3.0 * phi)};
    }
    case DragClosureKind::Ergun:
    case DragClosureKind::DiFelice:
    case DragClosureKind::MorsiAlexander:
      break;
  }
  return {eps, 0.0, 0.0};
}

double DragClosure::drag_coefficient(const DragInput& in, const PorosityFactors& factors) const {
  assert(factors.porosity == in.porosity);
  switch (kind_) {
    case DragClosureKind::SchillerNaumann:
      return schiller_naumann_with(in, factors.first, factors.second);
    case DragClosureKind::Ergun:
      return ergun_drag(in);
    case DragClosureKind::WenYu:
      return wen_yu_with(in, factors.first);
    case DragClosureKind::Gidaspow:
      return gidaspow_with(in, factors.first);
    case DragClosureKind::GidaspowBlend:
      return gidaspow_blend_with(in, factors.first, factors.second);
    case DragClosureKind::Beetstra:
      return beetstra_with(in, factors.first, factors.second);
    case DragClosureKind::DiFelice:
      return di_felice_drag(in);
    case DragClosureKind::MorsiAlexander:
      return morsi_alexander_drag(in);
  }
  return 0.0;
}

double DragClosure::momentum_exchange(const DragInput& in) const {
  return drag_coefficient(in) * (1.0 - in.porosity) / particle_volume(in.diameter);
}

double DragClosure::terminal_velocity(const DragInput& in) const {
  const double weight =
      particle_volume(in.diameter) * (in.particle_density - in.gas_density) * gravity_;
  if (weight <= 0.0) return 0.0;
  DragInput single = in;
  single.porosity = 1.0;
  single.sauter_diameter = in.diameter;
  auto excess = [&](double speed) {
    single.slip = speed;
    return drag_coefficient(single) * speed - weight;
  };
  return solve_increasing(excess, weight / stokes_coefficient(in));
}

double DragClosure::minimum_fluidization_velocity(const DragInput& in, double bed_porosity) const {
  const double eps = bed_porosity;
  const double weight =
      eps * particle_volume(in.diameter) * (in.particle_density - in.gas_density) * gravity_;
  if (weight <= 0.0) return 0.0;
  DragInput bed = in;
  bed.porosity = eps;
  auto excess = [&](double superficial) {
    bed.slip = superficial / eps;
    return drag_coefficient(bed) * bed.slip - weight;
  };
  return solve_increasing(excess, weight / stokes_coefficient(in));
}

}  // namespace carom
