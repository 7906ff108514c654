// The Monte Carlo method with a gas: the work of the gas forces is booked exactly (relax flights
// flown piece by piece, kicks by the kinetic energy they give), so the energy books close, and
// checkpoints carry it bit for bit. (The books through a shipped scene with the real gas solver:
// tests/test_gas_coupling.cpp, GasEnergyBooks/monte_carlo_*.)
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <filesystem>

#include "core/hdf5.hpp"
#include "events/monte_carlo/engine.hpp"
#include "monte_carlo_support.hpp"
#include "test_support.hpp"

namespace carom {
namespace {

/// A stand-in for the gas coupling: every 1.3 ms (not a multiple of the 1 ms step) it sets each
/// particle's relax flight towards a gas velocity that changes with time and height (rate
/// 1/tau = 30/s for the large, 100/s for the small spheres; the gas never lifts a sphere, so
/// none is pinned to the lid, and is vertical: a sideways gas pins spheres into the floor's
/// corners, where a relax flight bounces ever faster (100000 impacts in one 1 ms step seen:
/// the elastic-impact remedy is sized on gravity alone), and kicks: it takes 2 % of each velocity
/// and 5 % of each spin (as a drag or torque kick would).
void attach_fake_gas(MonteCarloEngine& mc) {
  mc.add_synchronising_action("fluid_step", mc.time(), 0.0013, [](GlobalStep& step) {
    ParticleStore& p = step.particles;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const double rate = p.species[i] == 0 ? 30.0 : 100.0;
      const Vec3 u(0.0, 0.0, 0.05 * std::cos(25.0 * step.time) + p.position[i].z());
      step.flights[i] = RelaxFlight{rate, rate * u + Vec3(0, 0, -9.81)};
      p.velocity[i] *= 0.98;
      p.spin[i] *= 0.95;
    }
  });
}

MonteCarloOptions relax_options(PartnerModel partner = PartnerModel::Gaussian) {
  MonteCarloOptions options;
  options.partner = partner;
  options.time_step = 1e-3;
  options.flight_model = FlightModel::Relax;
  return options;
}

// The books close: translational + rotational + potential + dissipated - gas work stays at its
// start value within 1e-9 of the gas work, at 40 times most of them inside steps (each particle
// shown at its last event, its flight since then booked on the fly). Every piece is exact
// (flights: the closed-form integral, RelaxFlight::move_booking_gas_work, tested in
// tests/test_relax_roots.cpp; kicks: the kinetic energy they change; collisions and wall impacts:
// the kinetic energy the particle loses booked as dissipated), so only round-off remains
// (measured: see the printout). The gas work must be large (at least the dissipated energy's
// tenth), so that a missing piece (e.g. the kicks, or the flights' remainder inside a step)
// fails by orders of magnitude. Both partner models.
TEST(MonteCarloGasWork, EnergyBooksCloseWithRelaxFlightsAndKicks) {
  for (const PartnerModel partner : {PartnerModel::Gaussian, PartnerModel::CellParticle}) {
    MonteCarloEngine mc(walled_box(5), relax_options(partner));
    attach_fake_gas(mc);
    const double start_total = mc.energies().total();
    double worst = 0.0;
    for (int k = 1; k <= 40; ++k) {
      mc.run_until(0.00271 * k);
      const Energies e = mc.energies();
      worst = std::max(worst, std::abs(e.total() - start_total) / std::abs(e.gas_work));
    }
    const Energies e = mc.energies();
    std::printf(
        "gas work %.4e J, dissipated %.4e J, kinetic %.4e J; books close to %.2e of the gas work\n",
        e.gas_work, e.dissipated, e.translational + e.rotational, worst);
    EXPECT_GT(mc.statistics().pair_events, 100u);
    EXPECT_GT(mc.statistics().wall_events, 100u);
    EXPECT_GT(std::abs(e.gas_work), 0.1 * std::abs(e.dissipated));
    EXPECT_LT(worst, 1e-9);
  }
}

// The gas work resumes bit for bit: saved inside a step and on a step boundary (0.0026 s, an
// action's time), restored from the HDF5 file, it equals the uninterrupted run's at the save time
// and at the end (with the particles). A checkpoint written before the gas work was booked (no
// attribute gas_work) still loads, with the gas work counted from 0 as the event-driven
// engine's do.
TEST(MonteCarloGasWork, ResumesBitForBitAndOldCheckpointsLoad) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "carom_mc_gas_resume";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "state.h5").string();
  MonteCarloEngine straight(walled_box(6), relax_options());
  attach_fake_gas(straight);
  straight.run_until(0.03);
  for (double save_at : {0.01237, 0.0026}) {
    MonteCarloEngine first(walled_box(6), relax_options());
    attach_fake_gas(first);
    first.run_until(save_at);
    {
      h5::File file = h5::File::create(path);
      first.save_state(file.create_group("method"));
    }
    {
      const h5::File file = h5::File::open(path, false);
      MonteCarloEngine resumed(walled_box(6), relax_options(),
                               read_monte_carlo_state(file.open_group("method")));
      attach_fake_gas(resumed);
      EXPECT_EQ(resumed.energies().gas_work, first.energies().gas_work) << "saved at " << save_at;
      resumed.run_until(0.03);
      ASSERT_EQ(resumed.time(), straight.time());
      for (std::size_t i = 0; i < straight.particle_count(); ++i) {
        ASSERT_EQ(resumed.position(i), straight.position(i)) << "particle " << i;
        ASSERT_EQ(resumed.velocity(i), straight.velocity(i)) << "particle " << i;
      }
      EXPECT_EQ(resumed.energies().gas_work, straight.energies().gas_work)
          << "saved at " << save_at;
      EXPECT_NE(straight.energies().gas_work, 0.0);
    }
  }
  // An older checkpoint: the same file without the attribute.
  {
    h5::File file = h5::File::open(path, true);
    const h5::Group method = file.open_group("method");
    ASSERT_TRUE(method.has_attribute("gas_work"));
    ASSERT_GE(H5Adelete(method.id(), "gas_work"), 0);
  }
  const h5::File file = h5::File::open(path, false);
  const MonteCarloState old = read_monte_carlo_state(file.open_group("method"));
  EXPECT_EQ(old.gas_work, 0.0);
  MonteCarloEngine resumed(walled_box(6), relax_options(), old);
  attach_fake_gas(resumed);
  resumed.run_until(0.03);
  for (std::size_t i = 0; i < straight.particle_count(); ++i)
    ASSERT_EQ(resumed.position(i), straight.position(i)) << "particle " << i;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace carom
