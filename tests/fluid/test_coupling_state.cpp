// The gas coupling's checkpoint (fluid/coupling_state.cpp): a coupling restored from save() into
// a fresh one continues bit for bit through the named HDF5 layout; a checkpoint that does not fit
// the scene is refused with the dataset and the shape it should have. And a step whose per-particle
// parts run in halves on a side thread gives the same bits as one thread. Determinism is exact, so
// every comparison is of bits.
#include <gtest/gtest.h>
#include <unistd.h>

#include <bit>
#include <cstdint>
#include <filesystem>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "core/hdf5.hpp"
#include "core/side_thread.hpp"
#include "fluid/coupling.hpp"
#include "fluid/porosity.hpp"
#include "tests/test_constants.hpp"

namespace carom {
namespace {

namespace fs = std::filesystem;

using carom::test::kGravity;
using carom::test::kGravityVector;
const std::vector<double> kSpeciesDensity{2500.0, 1500.0};  // kg/m^3

/// A small two-way bed: 3 x 2 x 6 gas cells of 4 mm over a box of 12 x 8 x 24 mm, an inlet
/// ramping up at the bottom, an outlet on top, free-slip sides; `cells` may change the grid.
struct Bed {
  Domain domain;
  GasSettings settings;
  ParticleStore particles;
  std::vector<RelaxFlight> flights;

  explicit Bed(std::array<int, 3> cells = {3, 2, 6}, std::uint32_t count = 60) {
    domain.lower = Vec3(0, 0, 0);
    domain.upper = Vec3(0.012, 0.008, 0.024);
    settings.coupling = CouplingLevel::TwoWay;
    settings.cells = cells;
    settings.time_step = 1e-3;
    settings.closure = DragClosureKind::Beetstra;  // Reads the Sauter diameters too.
    settings.sides[4].kind = GasSide::Kind::Inlet;
    settings.sides[4].velocity = 0.5;
    settings.sides[4].ramp_time = 0.01;
    settings.sides[5].kind = GasSide::Kind::Outlet;
    // Two species of beads, 1 mm and 0.6 mm, spread over the lower half, moving a little.
    std::mt19937 random(7);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    for (std::uint32_t i = 0; i < count; ++i) {
      const std::uint32_t s = i % 2;
      const double a = s == 0 ? 5e-4 : 3e-4;
      const double m = kSpeciesDensity[s] * 4.0 / 3.0 * std::numbers::pi * a * a * a;
      const Vec3 r(0.001 + 0.010 * uniform(random), 0.001 + 0.006 * uniform(random),
                   0.001 + 0.011 * uniform(random));
      const Vec3 v = 0.05 * Vec3(uniform(random) - 0.5, uniform(random) - 0.5, uniform(random));
      particles.add(r, v, Vec3::Zero(), a, m, 0.4 * m * a * a, s, i);
    }
  }

  std::unique_ptr<GasCoupling> coupling() const {
    return std::make_unique<GasCoupling>(settings, domain, std::vector<Wall>{}, kGravityVector,
                                         kSpeciesDensity);
  }
};

/// Fluid step n at t = n dt, then every particle flies its flight for dt (no collisions).
void advance(GasCoupling& gas, ParticleStore& particles, std::vector<RelaxFlight>& flights,
             int first, int steps, SideThread* side = nullptr) {
  const double dt = gas.settings().time_step;
  for (int n = first; n < first + steps; ++n) {
    gas.step(n * dt, particles, flights, side);
    for (std::size_t i = 0; i < particles.size(); ++i) {
      particles.position[i] += flights[i].displacement(particles.velocity[i], dt);
      particles.velocity[i] = flights[i].velocity(particles.velocity[i], dt);
    }
  }
}

std::uint64_t bits(double x) {
  return std::bit_cast<std::uint64_t>(x);
}

/// Every output of the coupling and every flight, bit for bit.
void expect_same_bits(const GasCoupling& a, const GasCoupling& b,
                      const std::vector<RelaxFlight>& fa, const std::vector<RelaxFlight>& fb) {
  auto same = [](const std::vector<double>& x, const std::vector<double>& y, const char* what) {
    ASSERT_EQ(x.size(), y.size()) << what;
    for (std::size_t k = 0; k < x.size(); ++k) ASSERT_EQ(bits(x[k]), bits(y[k])) << what << k;
  };
  auto same_vec = [](const Vec3& x, const Vec3& y, const char* what) {
    for (int k = 0; k < 3; ++k) EXPECT_EQ(bits(x[k]), bits(y[k])) << what << k;
  };
  same(a.pressure_field(), b.pressure_field(), "pressure ");
  same(a.porosity(), b.porosity(), "porosity ");
  const std::vector<Vec3> ua = a.velocity_field(), ub = b.velocity_field();
  ASSERT_EQ(ua.size(), ub.size());
  for (std::size_t c = 0; c < ua.size(); ++c) same_vec(ua[c], ub[c], "gas velocity ");
  ASSERT_EQ(fa.size(), fb.size());
  for (std::size_t i = 0; i < fa.size(); ++i) {
    EXPECT_EQ(bits(fa[i].rate), bits(fb[i].rate)) << "flight rate " << i;
    same_vec(fa[i].drive, fb[i].drive, "flight drive ");
  }
  same_vec(a.total_drag(), b.total_drag(), "total drag ");
  EXPECT_EQ(bits(a.pressure_drop()), bits(b.pressure_drop()));
  EXPECT_EQ(bits(a.momentum_inflow()), bits(b.momentum_inflow()));
  for (std::uint32_t s = 0; s < kSpeciesDensity.size(); ++s) {
    same_vec(a.mean_gas_velocity_at(s), b.mean_gas_velocity_at(s), "gas velocity seen ");
    same_vec(a.mean_gas_force_on(s), b.mean_gas_force_on(s), "gas force ");
    EXPECT_EQ(bits(a.mean_porosity_at(s)), bits(b.mean_porosity_at(s)));
  }
  EXPECT_EQ(a.times().steps, b.times().steps);
  EXPECT_EQ(a.times().unconverged_steps, b.times().unconverged_steps);
}

// The spheres' cell shares, drag coefficients and flights of a step computed in two halves on
// this and a side thread, their sums over particles taken in particle order: every output and
// flight the same bits as one thread's, for 8 steps (with the longitudinal rates kept, which
// call the closure twice per particle), and for an odd particle count (unequal halves).
// The per-particle loops go in pieces of 64 particles (kParticleChunk): one piece, several,
// and a last piece short of 64. The gas's momentum equations go x here, z beside and y's rows
// in two halves (a grid of 3 x 2 x 6 cells: every axis has unknowns).
TEST(CouplingHalves, ASideThreadGivesTheSameStepsBitForBit) {
  SideThread side;
  for (const std::size_t count : {60u, 59u, 300u, 263u}) {
    Bed one({3, 2, 6}, 300), two;
    while (one.particles.size() > count) one.particles.pop_back();
    two.particles = one.particles;
    auto alone = one.coupling(), shared = two.coupling();
    alone->keep_longitudinal_rates(true);
    shared->keep_longitudinal_rates(true);
    alone->prepare(one.particles);
    shared->prepare(two.particles);
    // The mapping against the plain loop over the particles, one sphere at a time.
    const SolidMapping oracle =
        map_solid_volume(CellLayout::over(one.domain, one.settings.cells), one.domain.periodic,
                         one.particles.position, one.particles.radius, alone->open_volume(),
                         one.settings.min_porosity);
    for (std::size_t c = 0; c < oracle.porosity.size(); ++c)
      ASSERT_EQ(bits(alone->porosity()[c]), bits(oracle.porosity[c])) << c;
    advance(*alone, one.particles, one.flights, 0, 8);
    advance(*shared, two.particles, two.flights, 0, 8, &side);
    expect_same_bits(*alone, *shared, one.flights, two.flights);
    for (std::size_t i = 0; i < count; ++i) {
      ASSERT_EQ(bits(alone->longitudinal_rates()[i]), bits(shared->longitudinal_rates()[i])) << i;
      for (int k = 0; k < 3; ++k)
        ASSERT_EQ(bits(alone->gas_velocity_at_particles()[i][k]),
                  bits(shared->gas_velocity_at_particles()[i][k]))
            << i;
    }
  }
}

class CouplingCheckpoint : public ::testing::Test {
 protected:
  void SetUp() override {
    path_ = (fs::temp_directory_path() /
             ("carom_coupling_state_" + std::to_string(getpid()) + "_" +
              ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".h5"))
                .string();
  }
  void TearDown() override { fs::remove(path_); }
  std::string path_;
};

// Four fluid steps (inside the inlet ramp, so the boundary's time dependence matters too), a
// save into /gas of a file, then four more steps: a fresh coupling restored from the file, with
// the particles as they were at the save, takes the same four steps to the last bit.
TEST_F(CouplingCheckpoint, RestoredFromNamedDatasetsContinuesBitForBit) {
  Bed bed;
  auto original = bed.coupling();
  original->prepare(bed.particles);
  advance(*original, bed.particles, bed.flights, 0, 4);
  ParticleStore particles_at_save = bed.particles;
  std::vector<RelaxFlight> flights_at_save = bed.flights;
  {
    h5::File file = h5::File::create(path_);
    original->save(file.create_group("gas"));
    file.close();
  }
  auto restored = Bed().coupling();
  {
    const h5::File file = h5::File::open(path_, false);
    restored->restore(file.open_group("gas"));
  }
  // Outputs read right after a restore are those of the saved coupling.
  expect_same_bits(*original, *restored, bed.flights, flights_at_save);
  advance(*original, bed.particles, bed.flights, 4, 4);
  advance(*restored, particles_at_save, flights_at_save, 4, 4);
  expect_same_bits(*original, *restored, bed.flights, flights_at_save);
  for (std::size_t i = 0; i < bed.particles.size(); ++i)
    for (int k = 0; k < 3; ++k)
      ASSERT_EQ(bits(bed.particles.velocity[i][k]), bits(particles_at_save.velocity[i][k]));
}

// The dataset names and shapes of the layout (documented in fluid/coupling_state.cpp), so that
// a change to them is a deliberate one.
TEST_F(CouplingCheckpoint, LayoutNamesEveryArray) {
  Bed bed;
  auto gas = bed.coupling();
  advance(*gas, bed.particles, bed.flights, 0, 1);
  h5::File file = h5::File::create(path_);
  const h5::Group group = file.create_group("gas");
  gas->save(group);
  const std::vector<std::string> expected{
      "face_velocity_x",   "face_velocity_y",      "face_velocity_z",  "fluid_steps",
      "inlet_drop_x",      "inlet_drop_y",         "inlet_drop_z",     "porosity",
      "pressure",          "previous_porosity",    "sauter_diameter",  "species_count",
      "species_gas_force", "species_gas_velocity", "species_porosity", "total_drag",
      "unconverged_steps", "wall_seconds"};
  EXPECT_EQ(group.children(), expected);
  EXPECT_EQ(group.open_dataset("pressure").shape(), (std::vector<hsize_t>{6, 2, 3}));
  EXPECT_EQ(group.open_dataset("face_velocity_x").shape(), (std::vector<hsize_t>{6, 2, 4}));
  EXPECT_EQ(group.open_dataset("face_velocity_z").shape(), (std::vector<hsize_t>{7, 2, 3}));
  EXPECT_EQ(group.open_dataset("species_gas_force").shape(), (std::vector<hsize_t>{2, 3}));
  EXPECT_EQ(group.read<std::uint64_t>("fluid_steps"), std::vector<std::uint64_t>{1});
}

// A checkpoint of another grid or another number of species is refused before anything
// changes, naming the dataset and the shape this scene needs.
TEST_F(CouplingCheckpoint, RefusesACheckpointOfAnotherScene) {
  Bed bed;
  auto gas = bed.coupling();
  advance(*gas, bed.particles, bed.flights, 0, 2);
  {
    h5::File file = h5::File::create(path_);
    gas->save(file.create_group("gas"));
  }
  const h5::File file = h5::File::open(path_, false);
  const h5::Group group = file.open_group("gas");
  auto message_of = [&](GasCoupling& other) {
    try {
      other.restore(group);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  auto taller = Bed({3, 2, 7}).coupling();
  const std::string grid = message_of(*taller);
  EXPECT_NE(grid.find("/gas/face_velocity_x"), std::string::npos) << grid;
  EXPECT_NE(grid.find("shape {6, 2, 4}"), std::string::npos) << grid;
  EXPECT_NE(grid.find("expected shape {7, 2, 4}"), std::string::npos) << grid;
  EXPECT_NE(grid.find("3 x 2 x 7 cells"), std::string::npos) << grid;

  Bed one_species;
  auto single = std::make_unique<GasCoupling>(one_species.settings, one_species.domain,
                                              std::vector<Wall>{}, kGravityVector, std::vector<double>{2500});
  const std::string species = message_of(*single);
  EXPECT_NE(species.find("/gas/species_count"), std::string::npos) << species;
  EXPECT_NE(species.find("expected shape {1}"), std::string::npos) << species;
  // Nothing was changed by the refused restore: the coupling is still at rest.
  EXPECT_EQ(single->times().steps, 0u);
}

}  // namespace
}  // namespace carom
