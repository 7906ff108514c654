#pragma once
/// The particle <-> gas coupling: the fluid step (core/DESIGN.md, "The gas and the two time
/// scales"). The kick flights' drag kicks, which read the flights set here, are
/// fluid/kick_scheme.hpp.
///
/// At a fluid step at time t (every particle synchronised to t):
///   1. each particle's volume is split over the gas cells it overlaps (exact sphere-cell
///      volumes, fluid/porosity.hpp); the same weights w_ic map particle quantities to cells and
///      interpolate cell quantities to particles, so the drag reaction on the gas is exactly
///      minus the sum of the drag forces on the particles;
///   2. porosity eps_c = 1 - solid_c / open_c; two-way: each cell's drag coefficient
///      beta_c = sum_i w_ic K_i / V_c and solid velocity sum_i w_ic K_i v_i / sum_i w_ic K_i,
///      with K_i from the closure at the slip seen before the solve;
///   3. the gas is advanced from t to t + dt (fluid/gas_solver.hpp, drag implicit);
///   4. each particle gets u_i, eps_i, grad p_i interpolated, K_i from the closure, and its
///      flight for the step: rate = K_i / m_i, drive = g + rate u_i - grad p_i / rho_p.
/// One-way coupling solves the gas with eps = 1 and no drag reaction; the particles still see
/// the local porosity in their closure.
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/domain.hpp"
#include "core/particles.hpp"
#include "core/relax_flight.hpp"
#include "core/side_thread.hpp"
#include "core/wall.hpp"
#include "gas_settings.hpp"
#include "gas_solver.hpp"
#include "porosity.hpp"

namespace carom {

class DragClosure;
namespace h5 {
class Group;
}  // namespace h5

/// Time spent in each part of the fluid steps, s of wall time (cumulative).
struct CouplingTimes {
  double mapping = 0;        ///< Splitting particles over cells, porosity, drag reaction.
  double solve = 0;          ///< The gas solver.
  double interpolation = 0;  ///< Gas fields at the particles, closures, flights.
  std::uint64_t steps = 0;   ///< Fluid steps taken.
  /// Fluid steps whose SIMPLE iterations stopped at the iteration limit before converging.
  std::uint64_t unconverged_steps = 0;
};

class GasCoupling {
 public:
  /// `species_density`: rho_p of each species (kg/m^3), indexed like ParticleStore::species.
  GasCoupling(const GasSettings& settings, const Domain& domain, const std::vector<Wall>& walls,
              const Vec3& gravity, std::vector<double> species_density);
  ~GasCoupling();
  GasCoupling(const GasCoupling&) = delete;
  GasCoupling& operator=(const GasCoupling&) = delete;

  /// Maps the particles (porosity) without advancing the gas: the state at t = 0 for outputs.
  void prepare(const ParticleStore& particles);
  /// The fluid step at time t: particles as of t; sets flights[i] for [t, t + dt).
  /// Its per-particle parts (the spheres' cell shares, drag coefficients and interpolation, in
  /// pieces taken in turn) run on this and the `side` thread when one is given;
  /// every sum over particles is taken in particle order afterwards, so the results are the same
  /// bit for bit.
  void step(double t, const ParticleStore& particles, std::vector<RelaxFlight>& flights,
            SideThread* side = nullptr);

  const GasSettings& settings() const { return settings_; }
  /// Inlet superficial velocity of side s at time t (the ramp applied), m/s.
  double inlet_velocity(int side, double t) const;
  /// Porosity of each gas cell at the last step.
  const std::vector<double>& porosity() const { return porosity_; }
  /// Gas volume available in each cell (inside the walls), m^3.
  const std::vector<double>& open_volume() const { return open_volume_; }
  /// The gas cell count per axis.
  std::array<int, 3> cells() const { return settings_.cells; }
  /// Gas pressure in every cell (x fastest, then y, then z), Pa.
  const std::vector<double>& pressure_field() const { return solver_->pressure_field(); }
  /// Interstitial gas velocity at every cell centre, m/s.
  std::vector<Vec3> velocity_field() const;
  /// Lower corner of the gas grid, m, and its cell size, m.
  const Vec3& grid_lower() const { return domain_.lower; }
  Vec3 cell_size() const { return layout_.cell_size(); }
  /// Mean gas pressure at the bottom face of the grid minus that at the top face (along z), Pa.
  /// An inlet face's pressure is the lowest cells' plus the drop across the half cell between
  /// the face and their centres (gas momentum: drag and weight); an outlet face's is the
  /// outlet pressure; a closed side's is extrapolated from the two outermost layers.
  double pressure_drop() const;
  /// Net rate at which the gas's z-momentum enters through the bottom and top sides, per unit
  /// area of a z face of the grid, Pa (rho_g U^2 (1/eps_bottom - 1) for a bed with inlet U).
  /// The force of the gas on the particles is pressure_drop() less the gas's weight per area
  /// plus this.
  double momentum_inflow() const;
  /// Mean interstitial gas velocity seen by the particles of species s at the last step, m/s.
  Vec3 mean_gas_velocity_at(std::uint32_t s) const;
  /// Mean force of the gas on a particle of species s at the last step: drag K_i (u_i - v_i)
  /// plus the pressure-gradient force -V_i grad p_i, N.
  Vec3 mean_gas_force_on(std::uint32_t s) const;
  /// Mean porosity interpolated to the particles of species s at the last step.
  double mean_porosity_at(std::uint32_t s) const;
  /// Interstitial gas velocity u_i at each particle at the last step (method order), m/s: what
  /// the spin forces' kicks read (fluid/kick_scheme.hpp).
  const std::vector<Vec3>& gas_velocity_at_particles() const { return particle_gas_velocity_; }
  /// Sum of the drag forces on the particles at the last step, N.
  const Vec3& total_drag() const { return total_drag_; }
  /// From the next step on, also keep each particle's longitudinal drag rate (one more drag
  /// evaluation per particle and step): what explicit kicks need for their stability check.
  void keep_longitudinal_rates(bool on) { keep_longitudinal_rates_ = on; }
  /// Per particle at the last step (method order; empty unless keep_longitudinal_rates), 1/s:
  /// (1/m_i) d|F|/d|s| at the slip s, F = K(|s|) s the drag. For a drag that grows faster than
  /// the slip (any Reynolds-number correction) it exceeds the secant rate K/m of the flights,
  /// and it is what limits an explicit step along the slip: the kick multiplies a small
  /// departure from the terminal velocity by 1 - dt_p times this rate.
  const std::vector<double>& longitudinal_rates() const { return longitudinal_rates_; }
  const CouplingTimes& times() const { return times_; }

  /// Writes the coupling's checkpoint into `group` (new datasets, one per array, doubles as
  /// native doubles): everything the next step and the outputs after it depend on (layout in
  /// fluid/coupling_state.cpp).
  void save(const h5::Group& group) const;
  /// Restores a save() of a coupling built from the same scene: the following steps reproduce
  /// the saved coupling's bit for bit. Throws std::invalid_argument naming the dataset and the
  /// shape expected when one is missing or does not fit this grid or species count.
  void restore(const h5::Group& group);

 private:
  void map_particles(const ParticleStore& particles, SideThread* side = nullptr);
  /// Side s's jet profile at time t (the ramp applied), m/s.
  std::vector<double> scaled_profile(int side, double t) const;
  /// `factors_kept`: step() left each particle's porosity factors in particle_factors_.
  void set_flights(const ParticleStore& particles, std::vector<RelaxFlight>& flights,
                   SideThread* side, bool factors_kept = false);
  /// What the closure needs of particle i at slip speed `slip` and porosity eps.
  DragInput drag_input(std::size_t i, const ParticleStore& particles, double eps,
                       double slip) const;

  GasSettings settings_;
  Domain domain_;
  Vec3 gravity_;
  std::vector<double> species_density_;
  std::unique_ptr<GasSolver> solver_;
  std::unique_ptr<DragClosure> closure_;
  std::array<std::vector<double>, 6> jet_profiles_;  ///< Inlet sides with jets: full profile, m/s.
  CellLayout layout_;
  std::vector<double> open_volume_;
  std::vector<double> porosity_;
  std::vector<double> sauter_;  ///< Sauter mean diameter per cell, m (0: the closure reads none).
  // Per particle, as of the last mapping.
  std::vector<std::size_t> weight_start_;        ///< Particle i's weights: [start[i], start[i+1]).
  std::vector<std::pair<int, double>> weights_;  ///< (cell, fraction of the particle's volume).
  // Per-particle scratch of a step, filled on two threads (see step).
  /// One piece's cell shares in order (map_particles), on a cache line of its own: the two
  /// threads append to theirs at once, and each append writes the vector's end (two pieces'
  /// vectors on one line moved it between the cores at every sphere).
  struct alignas(64) ChunkShares {
    std::vector<CellShare> shares;
  };
  std::vector<ChunkShares> chunk_shares_;
  std::vector<std::uint32_t> share_count_;             ///< Cell shares per particle.
  std::vector<double> particle_drag_;                  ///< K_i, kg/s.
  std::vector<PorosityFactors> particle_factors_;      ///< The closure's factors of eps_i.
  std::vector<double> particle_porosity_;              ///< eps_i interpolated.
  std::vector<Vec3> particle_pressure_gradient_;       ///< grad p_i interpolated, Pa/m.
  std::vector<Vec3> species_gas_velocity_;       ///< Sum of u_i per species (last step), m/s.
  std::vector<Vec3> species_gas_force_;          ///< Sum of K_i (u_i - v_i) - V_i grad p_i, N.
  std::vector<double> species_porosity_;         ///< Sum of eps_i per species (last step).
  std::vector<std::size_t> species_count_;       ///< Particles per species (last step).
  std::vector<Vec3> particle_gas_velocity_;      ///< u_i per particle (last step), m/s.
  /// Per gas cell, the solver's centre velocity (m/s) and pressure gradient (Pa/m), taken once
  /// before a loop over the particles reads them through their cell shares (each cell's value
  /// is then computed once, not once for every share of every particle in it).
  std::vector<Vec3> cell_gas_velocity_, cell_pressure_gradient_;
  /// Fills cell_gas_velocity_ (and cell_pressure_gradient_ when `gradient`) from the solver.
  void take_cell_fields(bool gradient);
  Vec3 total_drag_ = Vec3::Zero();
  bool keep_longitudinal_rates_ = false;
  std::vector<double> longitudinal_rates_;  ///< (1/m_i) d|F|/d|s| per particle (last step), 1/s.
  CouplingTimes times_;
};

}  // namespace carom
