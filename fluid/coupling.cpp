#include "coupling.hpp"

#include <algorithm>
#include <chrono>
#include <numbers>

#include "drag.hpp"
#include "gas_solver.hpp"
#include "porosity.hpp"

namespace carom {

namespace {
/// Particles per piece of the per-particle loops shared with the side thread (a drag closure
/// and an interpolation each, about a tenth of a microsecond: a piece of several microseconds).
constexpr std::size_t kParticleChunk = 64;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}
}  // namespace

GasCoupling::GasCoupling(const GasSettings& settings, const Domain& domain,
                         const std::vector<Wall>& walls, const Vec3& gravity,
                         std::vector<double> species_density)
    : settings_(settings),
      domain_(domain),
      gravity_(gravity),
      species_density_(std::move(species_density)) {
  layout_ = CellLayout::over(domain, settings.cells);
  open_volume_ = carom::open_volume(layout_, walls);
  GasGrid grid(domain.lower, domain.upper, settings.cells);
  grid.set_open_volume(open_volume_);
  std::array<GasBoundary, 6> boundaries;
  for (int s = 0; s < 6; ++s) {
    const GasSide& side = settings.sides[s];
    GasBoundary& b = boundaries[s];
    switch (side.kind) {
      case GasSide::Kind::Wall:
        b.kind = GasBoundaryKind::Wall;
        break;
      case GasSide::Kind::FreeSlip:
        b.kind = GasBoundaryKind::FreeSlip;
        break;
      case GasSide::Kind::Inlet:
        b.kind = GasBoundaryKind::Inlet;
        break;
      case GasSide::Kind::Outlet:
        b.kind = GasBoundaryKind::Outlet;
        break;
      case GasSide::Kind::Periodic:
        b.kind = GasBoundaryKind::Periodic;
        break;
    }
    b.pressure = side.pressure;
    b.superficial_velocity = inlet_velocity(s, 0.0);
    if (side.kind == GasSide::Kind::Inlet && !side.jets.empty()) {
      // Face cells whose centre lies in a jet blow at the jet's velocity.
      const int axis = s / 2, first = axis == 0 ? 1 : 0, second = axis == 2 ? 1 : 2;
      const Vec3 h = layout_.cell_size();
      std::vector<double> profile(std::size_t(settings.cells[first]) * settings.cells[second],
                                  side.velocity);
      for (int i = 0; i < settings.cells[first]; ++i)
        for (int j = 0; j < settings.cells[second]; ++j) {
          const double x = domain.lower[first] + (i + 0.5) * h[first];
          const double y = domain.lower[second] + (j + 0.5) * h[second];
          for (const InletJet& jet : side.jets)
            if (x >= jet.lower[0] && x <= jet.upper[0] && y >= jet.lower[1] && y <= jet.upper[1])
              profile[i + std::size_t(settings.cells[first]) * j] = jet.velocity;
        }
      jet_profiles_[s] = profile;
    }
  }
  for (int s = 0; s < 6; ++s)
    if (!jet_profiles_[s].empty()) boundaries[s].jet_profile = scaled_profile(s, 0.0);
  // SIMPLEC with light under-relaxation: about a third of the iterations of SIMPLE 0.7/0.3 in
  // beds (fluid/gas_solver.hpp), and as robust at fluid steps of ~1e-4 s.
  GasSolverOptions options;
  options.simplec = true;
  options.velocity_relaxation = 0.8;
  options.pressure_relaxation = 1.0;
  solver_ = std::make_unique<GasSolver>(std::move(grid),
                                        GasProperties{settings.density, settings.viscosity},
                                        boundaries, gravity, options);
  closure_ = std::make_unique<DragClosure>(settings.closure, settings.fluidization_porosity,
                                           gravity.norm() > 0 ? gravity.norm() : 9.81);
  porosity_.assign(layout_.count(), 1.0);
  sauter_.assign(layout_.count(), 0.0);
}

std::vector<double> GasCoupling::scaled_profile(int side, double t) const {
  const GasSide& s = settings_.sides[side];
  const double factor = (s.ramp_time > 0.0 && t < s.ramp_time) ? t / s.ramp_time : 1.0;
  std::vector<double> profile = jet_profiles_[side];
  for (double& u : profile) u *= factor;
  return profile;
}

void GasCoupling::prepare(const ParticleStore& particles) {
  map_particles(particles);
}

GasCoupling::~GasCoupling() = default;

double GasCoupling::inlet_velocity(int side, double t) const {
  const GasSide& s = settings_.sides[side];
  if (s.kind != GasSide::Kind::Inlet) return 0.0;
  if (s.ramp_time > 0.0 && t < s.ramp_time) return s.velocity * t / s.ramp_time;
  return s.velocity;
}

void GasCoupling::step(double t, const ParticleStore& particles, std::vector<RelaxFlight>& flights,
                       SideThread* side) {
  auto start = std::chrono::steady_clock::now();
  map_particles(particles, side);
  times_.mapping += seconds_since(start);

  start = std::chrono::steady_clock::now();
  const std::size_t cells = porosity_.size();
  std::vector<double> beta(cells, 0.0);
  std::vector<Vec3> solid_velocity(cells, Vec3::Zero());
  const bool two_way = settings_.coupling == CouplingLevel::TwoWay;
  if (two_way) {
    // Drag coefficients at the slip seen now (gas of the last step), mapped with the weights:
    // each particle's in pieces shared with the side thread, their sums in particle order. The
    // factors of the porosity alone are kept for set_flights, which reads the same porosity.
    const std::size_t n = particles.size();
    particle_drag_.resize(n);
    particle_factors_.resize(n);
    take_cell_fields(false);
    for_chunks(side, n, kParticleChunk, [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) {
        Vec3 u = Vec3::Zero();
        double eps = 0.0;
        for (std::size_t w = weight_start_[i]; w < weight_start_[i + 1]; ++w) {
          u += weights_[w].second * cell_gas_velocity_[weights_[w].first];
          eps += weights_[w].second * porosity_[weights_[w].first];
        }
        DragInput input = drag_input(i, particles, eps, (u - particles.velocity[i]).norm());
        particle_factors_[i] = closure_->porosity_factors(input);
        particle_drag_[i] = closure_->drag_coefficient(input, particle_factors_[i]);
      }
    });
    std::vector<double> k_sum(cells, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
      const double k = particle_drag_[i];
      for (std::size_t w = weight_start_[i]; w < weight_start_[i + 1]; ++w) {
        const auto [c, fraction] = weights_[w];
        k_sum[c] += fraction * k;
        solid_velocity[c] += fraction * k * particles.velocity[i];
      }
    }
    for (std::size_t c = 0; c < cells; ++c) {
      // The solver applies beta (u - v_s) per unit open volume of the cell.
      beta[c] = open_volume_[c] > 0.0 ? k_sum[c] / open_volume_[c] : 0.0;
      if (k_sum[c] > 0.0) solid_velocity[c] /= k_sum[c];
    }
  }
  const double t_new = t + settings_.time_step;
  for (int s = 0; s < 6; ++s) {
    if (settings_.sides[s].kind != GasSide::Kind::Inlet) continue;
    if (jet_profiles_[s].empty())
      solver_->set_inlet_velocity(s, inlet_velocity(s, t_new));
    else
      solver_->set_inlet_profile(s, scaled_profile(s, t_new));
  }
  const std::vector<double> gas_porosity = two_way ? porosity_ : std::vector<double>(cells, 1.0);
  const GasStepReport report =
      solver_->step(settings_.time_step, gas_porosity, beta, solid_velocity, side);
  if (!report.converged) ++times_.unconverged_steps;
  times_.solve += seconds_since(start);

  start = std::chrono::steady_clock::now();
  set_flights(particles, flights, side, two_way);
  times_.interpolation += seconds_since(start);
  ++times_.steps;
}

void GasCoupling::map_particles(const ParticleStore& particles, SideThread* side) {
  const std::size_t n = particles.size(), cells = porosity_.size();
  // Each sphere's cell shares (the geometry: most of the cost) in pieces taken in turn by this
  // and the side thread, each piece's in its own list...
  share_count_.resize(n);
  chunk_shares_.resize((n + kParticleChunk - 1) / kParticleChunk);
  for_chunks(side, n, kParticleChunk, [&](std::size_t begin, std::size_t end) {
    std::vector<CellShare>& shares = chunk_shares_[begin / kParticleChunk].shares;
    shares.clear();
    for (std::size_t i = begin; i < end; ++i) {
      const std::size_t before = shares.size();
      split_sphere(layout_, domain_.periodic, particles.position[i], particles.radius[i], shares);
      share_count_[i] = static_cast<std::uint32_t>(shares.size() - before);
    }
  });
  // ... then the weights and the cells' sums in particle order, as one thread would.
  weight_start_.assign(n + 1, 0);
  weights_.clear();
  // The Sauter sums only for the closures that read the mean diameter.
  const bool sauter = closure_->reads_sauter_diameter();
  std::vector<double> solid(cells, 0.0), d3(sauter ? cells : 0, 0.0), d2(sauter ? cells : 0, 0.0);
  const CellShare* share = nullptr;
  for (std::size_t i = 0; i < n; ++i) {
    if (i % kParticleChunk == 0) share = chunk_shares_[i / kParticleChunk].shares.data();
    weight_start_[i] = weights_.size();
    const double a = particles.radius[i];
    const double volume = 4.0 / 3.0 * std::numbers::pi * a * a * a;
    for (const CellShare* end = share + share_count_[i]; share != end; ++share) {
      weights_.emplace_back(share->cell, share->fraction);
      solid[share->cell] += share->fraction * volume;
      if (!sauter) continue;
      d3[share->cell] += share->fraction * 8.0 * a * a * a;
      d2[share->cell] += share->fraction * 4.0 * a * a;
    }
  }
  weight_start_[n] = weights_.size();
  for (std::size_t c = 0; c < cells; ++c) {
    porosity_[c] = open_volume_[c] > 0.0
                       ? std::max(settings_.min_porosity, 1.0 - solid[c] / open_volume_[c])
                       : 1.0;
    if (sauter) sauter_[c] = d2[c] > 0.0 ? d3[c] / d2[c] : 0.0;
  }
}

DragInput GasCoupling::drag_input(std::size_t i, const ParticleStore& particles, double eps,
                                  double slip) const {
  DragInput input{};
  input.porosity = eps;
  input.slip = slip;
  input.diameter = 2.0 * particles.radius[i];
  input.gas_density = settings_.density;
  input.gas_viscosity = settings_.viscosity;
  input.particle_density = species_density_[particles.species[i]];
  // Polydisperse closures: the particle's size relative to the local Sauter mean diameter.
  double sauter = 0.0;
  if (closure_->reads_sauter_diameter())
    for (std::size_t w = weight_start_[i]; w < weight_start_[i + 1]; ++w)
      sauter += weights_[w].second * sauter_[weights_[w].first];
  input.sauter_diameter = sauter > 0.0 ? sauter : input.diameter;
  return input;
}

void GasCoupling::take_cell_fields(bool gradient) {
  const std::size_t cells = porosity_.size();
  cell_gas_velocity_.resize(cells);
  for (std::size_t c = 0; c < cells; ++c)
    cell_gas_velocity_[c] = solver_->cell_velocity(static_cast<int>(c));
  if (!gradient) return;
  cell_pressure_gradient_.resize(cells);
  for (std::size_t c = 0; c < cells; ++c)
    cell_pressure_gradient_[c] = solver_->pressure_gradient(static_cast<int>(c));
}

void GasCoupling::set_flights(const ParticleStore& particles, std::vector<RelaxFlight>& flights,
                              SideThread* side, bool factors_kept) {
  const std::size_t n = particles.size();
  flights.resize(n);
  particle_gas_velocity_.resize(n);
  particle_drag_.resize(n);
  particle_porosity_.resize(n);
  particle_pressure_gradient_.resize(n);
  longitudinal_rates_.resize(keep_longitudinal_rates_ ? n : 0);
  take_cell_fields(true);
  // Each particle's gas, drag and flight in pieces shared with the side thread...
  for_chunks(side, n, kParticleChunk, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      Vec3 u = Vec3::Zero(), grad_p = Vec3::Zero();
      double eps = 0.0;
      for (std::size_t w = weight_start_[i]; w < weight_start_[i + 1]; ++w) {
        const auto [c, fraction] = weights_[w];
        u += fraction * cell_gas_velocity_[c];
        grad_p += fraction * cell_pressure_gradient_[c];
        eps += fraction * porosity_[c];
      }
      const Vec3& v = particles.velocity[i];
      const double slip = (u - v).norm();
      DragInput input = drag_input(i, particles, eps, slip);
      // The factors step() kept are those of this porosity (the same sums of the same weights);
      // the comparison makes that a check rather than an assumption.
      const PorosityFactors factors = factors_kept && particle_factors_[i].porosity == eps
                                          ? particle_factors_[i]
                                          : closure_->porosity_factors(input);
      const double k = closure_->drag_coefficient(input, factors);
      const double rate = k / particles.mass[i];
      if (keep_longitudinal_rates_) {
        // d(K s)/ds by a forward difference over a relative slip change of 1e-6 (the drag laws
        // are smooth there; at zero slip the derivative is K itself).
        const double ds = 1e-6 * slip;
        input.slip = slip + ds;
        const double tangent =
            slip > 0.0 ? (closure_->drag_coefficient(input, factors) * (slip + ds) - k * slip) / ds
                       : k;
        longitudinal_rates_[i] = std::max(rate, tangent / particles.mass[i]);
      }
      const std::uint32_t s = particles.species[i];
      flights[i] = RelaxFlight{rate, gravity_ + rate * u - grad_p / species_density_[s]};
      particle_gas_velocity_[i] = u;
      particle_drag_[i] = k;
      particle_porosity_[i] = eps;
      particle_pressure_gradient_[i] = grad_p;
    }
  });
  // ... and their sums in particle order.
  total_drag_ = Vec3::Zero();
  species_gas_velocity_.assign(species_density_.size(), Vec3::Zero());
  species_gas_force_.assign(species_density_.size(), Vec3::Zero());
  species_porosity_.assign(species_density_.size(), 0.0);
  species_count_.assign(species_density_.size(), 0);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& u = particle_gas_velocity_[i];
    const Vec3& v = particles.velocity[i];
    const double k = particle_drag_[i];
    const std::uint32_t s = particles.species[i];
    total_drag_ += k * (u - v);
    species_gas_velocity_[s] += u;
    species_gas_force_[s] +=
        k * (u - v) - (particles.mass[i] / species_density_[s]) * particle_pressure_gradient_[i];
    species_porosity_[s] += particle_porosity_[i];
    ++species_count_[s];
  }
}

Vec3 GasCoupling::mean_gas_force_on(std::uint32_t s) const {
  if (s >= species_count_.size() || species_count_[s] == 0) return Vec3::Zero();
  return species_gas_force_[s] / static_cast<double>(species_count_[s]);
}

double GasCoupling::mean_porosity_at(std::uint32_t s) const {
  if (s >= species_count_.size() || species_count_[s] == 0) return 0.0;
  return species_porosity_[s] / static_cast<double>(species_count_[s]);
}

Vec3 GasCoupling::mean_gas_velocity_at(std::uint32_t s) const {
  if (s >= species_count_.size() || species_count_[s] == 0) return Vec3::Zero();
  return species_gas_velocity_[s] / static_cast<double>(species_count_[s]);
}

std::vector<Vec3> GasCoupling::velocity_field() const {
  std::vector<Vec3> u(porosity_.size());
  for (std::size_t c = 0; c < u.size(); ++c) u[c] = solver_->cell_velocity(static_cast<int>(c));
  return u;
}

double GasCoupling::momentum_inflow() const {
  const Vec3 size = domain_.upper - domain_.lower;
  return (solver_->momentum_inflow(4) + solver_->momentum_inflow(5)) / (size.x() * size.y());
}

double GasCoupling::pressure_drop() const {
  const int nz = settings_.cells[2], layer = settings_.cells[0] * settings_.cells[1];
  auto mean = [&](int k) {
    double sum = 0.0;
    for (int c = 0; c < layer; ++c) sum += solver_->pressure(k * layer + c);
    return sum / layer;
  };
  if (nz < 2) return 0.0;
  // An inlet face's pressure: the lowest cells' plus the drop across the half cell to the face
  // (GasSolver::inlet_drop; z face c lies below cell c); an outlet face's: the outlet pressure.
  // Other sides: linear extrapolation from the two outermost layers of cell centres.
  double inlet_drop = 0.0;
  for (int c = 0; c < layer; ++c) inlet_drop += solver_->inlet_drop(2, c);
  const double bottom = settings_.sides[4].kind == GasSide::Kind::Inlet
                            ? mean(0) + inlet_drop / layer
                            : 1.5 * mean(0) - 0.5 * mean(1);
  const double top = settings_.sides[5].kind == GasSide::Kind::Outlet
                         ? settings_.sides[5].pressure
                         : 1.5 * mean(nz - 1) - 0.5 * mean(nz - 2);
  return bottom - top;
}

}  // namespace carom
