// Output layer: the HDF5 wrapper, the run file and its XDMF sidecar, checkpoints.
//
// What matters physically is that a checkpoint is the whole dynamic state: a run restored from
// one continues bit for bit as the run that was never interrupted. Everything else here checks
// that what is written is what was simulated (bit for bit where it is a copy of the state).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <numeric>
#include <regex>
#include <sstream>
#include <tuple>

#include "checkpoint_support.hpp"
#include "core/hdf5.hpp"
#include "scenarios/run/run_output.hpp"
#include "scenarios/run/xdmf_sidecar.hpp"
#include "scenarios/scene/granular_gas.hpp"
#include "test_support.hpp"

namespace carom {
namespace {

namespace fs = std::filesystem;

/// A fresh, empty directory per test, removed at the end.
class OutputTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    directory_ = fs::temp_directory_path() /
                 ("carom_output_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(directory_);
    fs::create_directories(directory_);
  }
  void TearDown() override { fs::remove_all(directory_); }
  std::string file(const std::string& name) const { return (directory_ / name).string(); }

  fs::path directory_;
};

/// A small, dense, inelastic periodic gas: many collisions per unit time, dissipation booked.
GranularGasSpec small_gas() {
  GranularGasSpec spec;
  spec.count = 108;
  spec.volume_fraction = 0.25;
  spec.restitution = 0.9;
  spec.seed = 7;
  return spec;
}

RunInfo test_info() {
  return RunInfo{"[meta]\nname = \"test\"\n# ünïcode\n", "test", 42};
}

std::uint64_t bits(double x) {
  return std::bit_cast<std::uint64_t>(x);
}

/// Byte-wise equality of two arrays of trivially copyable, unpadded values (doubles compared as
/// bit patterns, so -0.0 != 0.0 and NaN payloads count).
template <class T>
void expect_same_bits(const std::vector<T>& a, const std::vector<T>& b, const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  if (!a.empty()) {
    EXPECT_EQ(0, std::memcmp(a.data(), b.data(), a.size() * sizeof(T))) << what;
  }
}

/// Every field of two engine states, bit for bit.
void expect_same_state(const EngineState& a, const EngineState& b) {
  const ParticleStore &p = a.particles, &q = b.particles;
  expect_same_bits(p.position, q.position, "position");
  expect_same_bits(p.velocity, q.velocity, "velocity");
  expect_same_bits(p.clock, q.clock, "clock");
  expect_same_bits(p.radius, q.radius, "radius");
  expect_same_bits(a.event_counters, b.event_counters, "event_counter");
  expect_same_bits(p.spin, q.spin, "spin");
  expect_same_bits(p.mass, q.mass, "mass");
  expect_same_bits(p.inertia, q.inertia, "inertia");
  expect_same_bits(a.last_collision, b.last_collision, "last_collision");
  expect_same_bits(p.species, q.species, "species");
  expect_same_bits(p.id, q.id, "id");
  expect_same_bits(a.cells, b.cells, "cells");
  for (const auto& [x, y, what] : {std::tuple{&a.events, &b.events, "event"},
                                   std::tuple{&a.crossings, &b.crossings, "crossing"}}) {
    ASSERT_EQ(x->size(), y->size()) << what;
    for (std::size_t i = 0; i < x->size(); ++i) {
      EXPECT_EQ(bits((*x)[i].time), bits((*y)[i].time)) << what << " " << i;
      EXPECT_EQ((*x)[i].partner, (*y)[i].partner) << what << " " << i;
      EXPECT_EQ((*x)[i].partner_counter, (*y)[i].partner_counter) << what << " " << i;
      EXPECT_EQ((*x)[i].kind, (*y)[i].kind) << what << " " << i;
    }
  }
  EXPECT_EQ(bits(a.time), bits(b.time));
  EXPECT_EQ(bits(a.last_particle_event), bits(b.last_particle_event));
  const RunStatistics &s = a.statistics, &t = b.statistics;
  EXPECT_EQ(s.species_count, t.species_count);
  EXPECT_EQ(s.wall_count, t.wall_count);
  expect_same_bits(s.pair_collisions, t.pair_collisions, "pair_collisions");
  expect_same_bits(s.wall_collisions, t.wall_collisions, "wall_collisions");
  expect_same_bits(s.wall_impulse, t.wall_impulse, "wall_impulse");
  EXPECT_EQ(0, std::memcmp(s.virial.data(), t.virial.data(), 9 * sizeof(double))) << "virial";
  EXPECT_EQ(bits(s.dissipated_energy), bits(t.dissipated_energy));
  EXPECT_EQ(s.events, t.events);
  EXPECT_EQ(s.invalid_events, t.invalid_events);
  EXPECT_EQ(s.pair_events, t.pair_events);
  EXPECT_EQ(s.wall_events, t.wall_events);
  EXPECT_EQ(s.cell_crossings, t.cell_crossings);
  expect_same_bits(a.stall_window_start, b.stall_window_start, "stall_window_start");
  expect_same_bits(a.stall_count, b.stall_count, "stall_count");
  EXPECT_EQ(bits(a.stall_window), bits(b.stall_window));
  ASSERT_EQ(a.action_times.size(), b.action_times.size());
  for (std::size_t k = 0; k < a.action_times.size(); ++k) {
    EXPECT_EQ(a.action_times[k].first, b.action_times[k].first);
    EXPECT_EQ(bits(a.action_times[k].second), bits(b.action_times[k].second));
  }
}

// ---- the HDF5 wrapper -------------------------------------------------------------------------

TEST_F(OutputTest, Hdf5WrapperRoundTripsNumbersStringsAndRows) {
  const std::vector<double> awkward{0.1,    -0.0,    std::numeric_limits<double>::denorm_min(),
                                    kNever, -kNever, std::nan("0x5eed"),
                                    1e308,  6.0};
  const std::vector<std::uint64_t> large{0, 1, std::numeric_limits<std::uint64_t>::max()};
  {
    h5::File f = h5::File::create(file("a.h5"));
    const h5::Group g = f.create_group("group");
    g.write("matrix", awkward, {4, 2});
    g.write("large", large);
    g.write("empty", std::vector<double>{});
    g.write_string("text", "line 1\nline 2 ✓");
    g.write_string("nothing", "");
    g.write_strings("names", {"x_low", "", "a longer name"});
    g.set_attribute("time", awkward[0]);
    g.set_attribute("label", "hello");
    g.set_attribute("count", std::uint64_t{12});
    g.set_attribute("lower", std::vector<double>{1, 2, 3});
    const h5::Dataset rows = g.create_extendible<double>("rows", 3);
    rows.append(std::vector<double>{1, 2, 3});
    rows.append(std::vector<double>{4, 5, 6, 7, 8, 9});
    const h5::Dataset series = g.create_extendible<std::uint64_t>("series", 0);
    for (std::uint64_t k = 0; k < 2000; ++k) series.append(std::vector<std::uint64_t>{k * k});
    EXPECT_THROW(rows.append(std::vector<double>{1, 2}), std::runtime_error);  // half a row
    f.close();
  }
  const h5::File f = h5::File::open(file("a.h5"), false);
  const h5::Group g = f.open_group("group");
  expect_same_bits(g.read<double>("matrix", {4, 2}), awkward, "matrix");
  expect_same_bits(g.read<std::uint64_t>("large"), large, "large");
  EXPECT_TRUE(g.read<double>("empty").empty());
  EXPECT_EQ(g.read_string("text"), "line 1\nline 2 ✓");
  EXPECT_EQ(g.read_string("nothing"), "");
  EXPECT_EQ(g.read_strings("names"), (std::vector<std::string>{"x_low", "", "a longer name"}));
  EXPECT_EQ(bits(g.attribute<double>("time")), bits(0.1));
  EXPECT_EQ(g.attribute<std::string>("label"), "hello");
  EXPECT_EQ(g.attribute<std::uint64_t>("count"), 12u);
  EXPECT_EQ(g.attribute_vector<double>("lower"), (std::vector<double>{1, 2, 3}));
  EXPECT_EQ(g.read<double>("rows", {3, 3}), (std::vector<double>{1, 2, 3, 4, 5, 6, 7, 8, 9}));
  const std::vector<std::uint64_t> series = g.read<std::uint64_t>("series", {2000});
  EXPECT_EQ(series[1999], 1999u * 1999u);
  EXPECT_EQ(f.children(), (std::vector<std::string>{"group"}));
  EXPECT_TRUE(f.contains("group/rows"));
  EXPECT_FALSE(f.contains("group/missing/deeper"));

  // Errors name the file and the object.
  try {
    g.read<double>("matrix", {8});
    FAIL() << "a wrong shape must throw";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(file("a.h5") + ":/group/matrix"), std::string::npos)
        << e.what();
  }
  try {
    g.open_dataset("missing");
    FAIL() << "a missing dataset must throw";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(":/group: has no dataset 'missing'"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(h5::File::open(file("does_not_exist.h5"), false), std::runtime_error);
}

// ---- the run file -----------------------------------------------------------------------------

TEST_F(OutputTest, SnapshotHoldsTheStateAtTheCurrentTimeBitForBit) {
  EventDrivenEngine sim(make_granular_gas(small_gas()));
  sim.run_until(0.37);
  {
    RunFile run(file("run.h5"), test_info(), sim.system());
    run.write_snapshot(sim);
  }
  const h5::File f = h5::File::open(file("run.h5"), false);
  EXPECT_EQ(f.attribute<std::string>("scene_name"), "test");
  EXPECT_EQ(f.attribute<std::uint64_t>("seed"), 42u);
  EXPECT_EQ(f.read_string("scene"), test_info().scene_text);
  EXPECT_EQ(f.open_group("species").read_strings("name"), std::vector<std::string>{"large"});

  const h5::Group snapshot = f.open_group("snapshots/000000");
  EXPECT_EQ(bits(snapshot.attribute<double>("time")), bits(sim.time()));
  const std::size_t n = sim.particle_count();
  const auto position = snapshot.read<double>("position", {n, 3});
  const auto velocity = snapshot.read<double>("velocity", {n, 3});
  const auto spin = snapshot.read<double>("spin", {n, 3});
  const auto radius = snapshot.read<double>("radius", {n});
  const auto species = snapshot.read<std::int32_t>("species", {n});
  const auto id = snapshot.read<std::int64_t>("id", {n});
  std::map<std::uint64_t, std::size_t> row_of_id;
  for (std::size_t k = 0; k < n; ++k) row_of_id[static_cast<std::uint64_t>(id[k])] = k;
  ASSERT_EQ(row_of_id.size(), n) << "every particle exactly once";
  EXPECT_TRUE(std::is_sorted(id.begin(), id.end())) << "rows in id order";
  const ParticleStore& p = sim.system().particles;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t k = row_of_id.at(p.id[i]);
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(bits(position[3 * k + c]), bits(sim.position(i)[c]));
      EXPECT_EQ(bits(velocity[3 * k + c]), bits(sim.velocity(i)[c]));
      EXPECT_EQ(bits(spin[3 * k + c]), bits(sim.spin(i)[c]));
    }
    EXPECT_EQ(bits(radius[k]), bits(p.radius[i]));
    EXPECT_EQ(species[k], static_cast<std::int32_t>(p.species[i]));
  }
}

// The pressure tensor of an elastic hard-sphere fluid from the collision virial plus the kinetic
// part must give the Carnahan-Starling equation of state, Z = P / (n T) = (1 + phi + phi^2 -
// phi^3) / (1 - phi)^3 = 2.406 at phi = 0.2 (CS is within 0.5 % of simulations there), and the
// pair collision rate the Enskog value N omega / 2. About 60 000 collisions: statistical error
// near 1 %, O(1/N) finite-size effects below 1 % for N = 500; hence 3 %.
TEST_F(OutputTest, TimeSeriesPressureAndCollisionRateMatchKineticTheory) {
  GranularGasSpec spec;
  spec.count = 500;
  spec.volume_fraction = 0.2;
  spec.restitution = 1.0;
  spec.seed = 3;
  EventDrivenEngine sim(make_granular_gas(spec));
  const double sample_interval = 2.0;
  {
    RunFile run(file("run.h5"), test_info(), sim.system());
    sim.add_periodic_action("sample", sample_interval, sample_interval,
                            [&] { run.append_sample(sim); });
    sim.run_until(51.0);  // samples at 2, 4, ..., 50
  }
  const h5::File f = h5::File::open(file("run.h5"), false);
  const h5::Group series = f.open_group("timeseries");
  const auto time = series.read<double>("time");
  const std::size_t rows = time.size();
  ASSERT_EQ(rows, 25u);
  const auto pressure = series.read<double>("pressure_tensor", {rows, 9});
  const auto kinetic = series.read<double>("kinetic_translational", {rows});
  const auto dissipated = series.read<double>("dissipated", {rows});
  const auto total = series.read<double>("total_energy", {rows});
  const auto pair = series.read<std::uint64_t>("pair_collisions", {rows, 1});
  const auto rate = series.read<double>("collision_rate", {rows});
  EXPECT_FALSE(f.contains("timeseries/wall_collisions")) << "no walls in a periodic gas";

  const double volume = sim.system().domain.volume();
  const double phi = spec.volume_fraction;
  const double z_cs = (1 + phi + phi * phi - phi * phi * phi) / std::pow(1 - phi, 3);
  double mean_ratio = 0, off_diagonal = 0;
  for (std::size_t r = 0; r < rows; ++r) {
    const double kinetic_pressure = 2.0 * kinetic[r] / (3.0 * volume);  // n T with T = 2K/(3N)
    mean_ratio += (pressure[9 * r] + pressure[9 * r + 4] + pressure[9 * r + 8]) / 3.0 /
                  kinetic_pressure / rows;
    off_diagonal = std::max({off_diagonal, std::abs(pressure[9 * r + 1]) / kinetic_pressure,
                             std::abs(pressure[9 * r + 5]) / kinetic_pressure});
    EXPECT_NEAR(dissipated[r], 0.0, 1e-9 * total[0]) << "only round-off when e = 1";
    EXPECT_NEAR(total[r], total[0], 1e-9 * total[0]) << "energy is conserved when e = 1";
  }
  EXPECT_NEAR(mean_ratio, z_cs, 0.03 * z_cs);
  EXPECT_LT(off_diagonal, 0.15) << "a fluid at rest has no shear stress";

  const std::size_t n = sim.particle_count();
  const double temperature = 2.0 * kinetic[0] / (3.0 * (n - 1.0));
  const double mass = sim.system().species[0].mass();
  const double omega =
      test::enskog_collision_rate(n / volume, spec.diameter, phi, temperature, mass);
  const double measured = static_cast<double>(pair.back()) / time.back();
  EXPECT_NEAR(measured, 0.5 * n * omega, 0.03 * 0.5 * n * omega);
  double mean_rate = 0;
  for (double r : rate) mean_rate += r / rows;
  EXPECT_NEAR(mean_rate, measured, 1e-9 * measured) << "rates over equal intervals average out";
}

// ---- the XDMF sidecar -------------------------------------------------------------------------

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in.good()) << path;
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

/// Checks the HDF5 references of one grid's body: each dataset exists with the stated
/// dimensions and number type, is relative to the sidecar, and has `rows` rows. Returns how many.
std::size_t check_data_items(const std::string& body, const h5::File& f,
                             const std::string& data_file, std::size_t rows) {
  const std::regex item_pattern(
      R"re(<DataItem Dimensions="([\d ]+)" NumberType="(\w+)" Precision="(\d)" Format="HDF">([^:<]+):([^<]+)</DataItem>)re");
  std::size_t items = 0;
  for (std::sregex_iterator it(body.begin(), body.end(), item_pattern), end; it != end;
       ++it, ++items) {
    const std::smatch& item = *it;
    EXPECT_EQ(item[4].str(), data_file) << "references are relative to the sidecar";
    const h5::Dataset dataset = f.open_dataset(item[5].str());
    std::vector<hsize_t> dims;
    std::istringstream dimension_text(item[1].str());
    for (hsize_t d; dimension_text >> d;) dims.push_back(d);
    EXPECT_EQ(dataset.shape(), dims) << item[5];
    EXPECT_EQ(dims[0], rows) << item[5];
    // The stated number type is the stored one.
    const hid_t type = H5Dget_type(dataset.id());
    EXPECT_EQ(H5Tget_size(type), std::stoul(item[3])) << item[5];
    EXPECT_EQ(H5Tget_class(type) == H5T_FLOAT, item[2] == "Float") << item[5];
    H5Tclose(type);
  }
  return items;
}

/// Checks every grid of the particles' sidecar against the HDF5 file: each referenced dataset
/// exists with the stated dimensions, the point count matches, the connectivity makes one
/// vertex cell of each particle (0, 1, ..., n - 1: what ParaView's Xdmf3 readers need to make
/// cells at all), and the time is the snapshot's. Returns the number of grids.
std::size_t check_xdmf(const std::string& xmf, const std::string& h5_path) {
  const std::string text = read_text(xmf);
  EXPECT_NE(
      text.find("<Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">"),
      std::string::npos);
  EXPECT_EQ(text.find("</Xdmf>"), text.size() - 8) << "a complete document";
  EXPECT_EQ(text.find("gas"), std::string::npos) << "the gas has its own sidecar";

  const h5::File f = h5::File::open(h5_path, false);
  const std::string data_file = fs::path(h5_path).filename().string();
  const std::regex grid_pattern(
      R"re(<Grid Name="particles_(\d+)" GridType="Uniform">([\s\S]*?)</Grid>)re");
  const std::regex time_pattern(R"re(<Time Value="([^"]+)"/>)re");
  const std::regex topology_pattern(
      R"re(<Topology TopologyType="Polyvertex" NumberOfElements="(\d+)" NodesPerElement="1">\s*<DataItem [^>]*>[^:<]+:([^<]+)</DataItem>\s*</Topology>)re");
  std::size_t grids = 0;
  for (std::sregex_iterator g(text.begin(), text.end(), grid_pattern), end; g != end;
       ++g, ++grids) {
    const std::string name = (*g)[1], body = (*g)[2];
    SCOPED_TRACE("grid " + name);
    std::smatch m;
    if (!std::regex_search(body, m, topology_pattern)) {
      ADD_FAILURE() << "no Polyvertex topology with its connectivity in " << body;
      continue;
    }
    const std::size_t points = std::stoul(m[1]);
    EXPECT_EQ(f.open_group("snapshots/" + name).open_dataset("radius").size(), points);
    const std::vector<std::int64_t> vertices = f.read<std::int64_t>(m[2].str());
    std::vector<std::int64_t> rows(points);
    std::iota(rows.begin(), rows.end(), std::int64_t{0});
    EXPECT_EQ(vertices, rows) << "vertex cell k is particle row k";
    const double time = f.open_group("snapshots/" + name).attribute<double>("time");
    if (std::regex_search(body, m, time_pattern)) {
      EXPECT_EQ(std::stod(m[1]), time) << "17 digits give the double back";
    } else {
      ADD_FAILURE() << "no Time in " << body;
    }
    EXPECT_EQ(check_data_items(body, f, data_file, points), 7u)
        << "connectivity, position, radius, velocity, spin, species, id";
  }
  return grids;
}

TEST_F(OutputTest, XdmfSidecarReferencesEverySnapshotDataset) {
  GranularGasSpec spec = small_gas();
  spec.fines_diameter_ratio = 0.5;  // two species: species data must be right too
  spec.fines_number_fraction = 0.5;
  spec.volume_fraction = 0.15;
  EventDrivenEngine sim(make_granular_gas(spec));
  auto run = std::make_unique<RunFile>(file("run.h5"), test_info(), sim.system());
  sim.add_periodic_action("snapshot", 0.0, 0.25, [&] { run->write_snapshot(sim); });
  sim.run_until(0.6);  // snapshots at 0, 0.25, 0.5
  EXPECT_EQ(check_xdmf(file("run.xmf"), file("run.h5")), 3u) << "readable while running";
  run.reset();
  EXPECT_EQ(check_xdmf(file("run.xmf"), file("run.h5")), 3u);

  // Appending (as `carom resume` does) adds snapshots after the existing ones.
  run = RunFile::append(file("run.h5"));
  sim.run_until(0.8);  // a snapshot at 0.75
  run.reset();
  EXPECT_EQ(check_xdmf(file("run.xmf"), file("run.h5")), 4u);
  EXPECT_FALSE(fs::exists(file("run.xmf.tmp")));
}

// The gas's sidecar: a uniform grid whose node counts, origin and spacing are listed z, y, x
// (XDMF's order for 3DCoRectMesh and ORIGIN_DXDYDZ) and whose cell fields are the snapshot's.
// The cells, origin and spacing differ on every axis, so a swapped axis shows.
TEST_F(OutputTest, GasSidecarListsTheGridZYX) {
  const XdmfGasGrid grid{{2, 3, 4}, Vec3(-1.0, -2.0, -3.0), Vec3(0.5, 0.25, 0.125)};
  {
    const h5::File f = h5::File::create(file("run.h5"));
    const h5::Group snapshots = f.create_group("snapshots");
    for (const char* snapshot : {"000000", "000001"}) {
      const h5::Group fields = snapshots.create_group(snapshot).create_group("gas");
      fields.write("porosity", std::vector<double>(24, 0.5), {4, 3, 2});
      fields.write("pressure", std::vector<double>(24, 1e5), {4, 3, 2});
      fields.write("velocity", std::vector<double>(72, 0.0), {4, 3, 2, 3});
    }
  }
  write_xdmf_sidecars(file("run.h5"), {{"000000", 0.0, 0}, {"000001", 0.5, 0}}, &grid);
  EXPECT_EQ(gas_xdmf_path_of(file("run.h5")), file("run_gas.xmf"));
  const std::string text = read_text(file("run_gas.xmf"));
  EXPECT_NE(text.find("<Grid Name=\"gas\" GridType=\"Collection\" CollectionType=\"Temporal\">"),
            std::string::npos);
  const h5::File f = h5::File::open(file("run.h5"), false);
  const std::regex grid_pattern(
      R"re(<Grid Name="gas_(\d+)" GridType="Uniform">([\s\S]*?)</Grid>)re");
  std::size_t grids = 0;
  for (std::sregex_iterator g(text.begin(), text.end(), grid_pattern), end; g != end;
       ++g, ++grids) {
    const std::string body = (*g)[2];
    EXPECT_NE(body.find("<Time Value=\"" + std::string(grids == 0 ? "0" : "0.5") + "\"/>"),
              std::string::npos)
        << body;
    EXPECT_NE(body.find("<Topology TopologyType=\"3DCoRectMesh\" Dimensions=\"5 4 3\"/>"),
              std::string::npos)
        << body;
    EXPECT_NE(body.find("<DataItem Dimensions=\"3\" NumberType=\"Float\" Precision=\"8\" "
                        "Format=\"XML\">-3 -2 -1</DataItem>"),
              std::string::npos)
        << body;
    EXPECT_NE(body.find("<DataItem Dimensions=\"3\" NumberType=\"Float\" Precision=\"8\" "
                        "Format=\"XML\">0.125 0.25 0.5</DataItem>"),
              std::string::npos)
        << body;
    EXPECT_NE(body.find("/snapshots/" + (*g)[1].str() + "/gas/porosity"), std::string::npos)
        << body;
    EXPECT_EQ(check_data_items(body, f, "run.h5", 4), 3u) << "porosity, pressure, velocity";
  }
  EXPECT_EQ(grids, 2u);
}

TEST_F(OutputTest, AppendContinuesTheTimeSeries) {
  EventDrivenEngine sim(make_granular_gas(small_gas()));
  {
    RunFile run(file("run.h5"), test_info(), sim.system());
    for (double t : {0.5, 1.0}) {
      sim.run_until(t);
      run.append_sample(sim);
    }
  }
  std::unique_ptr<RunFile> run = RunFile::append(file("run.h5"));
  EXPECT_EQ(run->path(), file("run.h5"));
  sim.run_until(1.5);
  run->append_sample(sim);
  run.reset();
  const h5::File f = h5::File::open(file("run.h5"), false);
  const h5::Group series = f.open_group("timeseries");
  EXPECT_EQ(series.read<double>("time"), (std::vector<double>{0.5, 1.0, 1.5}));
  const auto events = series.read<std::uint64_t>("events");
  const auto event_rate = series.read<double>("event_rate");
  // The rate of the appended row covers (1.0, 1.5], as if the file had never been closed.
  EXPECT_DOUBLE_EQ(event_rate[2], (events[2] - events[1]) / 0.5);
  EXPECT_GT(series.read<double>("dissipated").back(), 0.0) << "e = 0.9 dissipates";
  EXPECT_THROW(read_checkpoint(file("run.h5")), std::runtime_error)
      << "a run file is no checkpoint";
}

// Rows wait in memory until they are written together (RunFile::kRowWait). A writer killed
// without a chance to clean up (here: a child process that ends with _exit, no destructor) leaves
// a readable file with every row written before the kill and none of those still waiting; with a
// row wait of 0 every row is written at once.
TEST_F(OutputTest, RowsWrittenSurviveAKilledWriterAndWaitingRowsDoNot) {
  EventDrivenEngine sim(make_granular_gas(small_gas()));
  auto killed_writer = [&](const std::string& path, double row_wait) {
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      RunFile run(path, test_info(), sim.system());
      run.set_row_wait(row_wait);
      sim.run_until(0.5);
      run.append_sample(sim);
      run.write_waiting_rows();
      for (double t : {1.0, 1.5}) {
        sim.run_until(t);
        run.append_sample(sim);
      }
      _exit(0);
    }
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  };
  killed_writer(file("waiting.h5"), 3600.0);  // an hour: the child runs for milliseconds
  killed_writer(file("at_once.h5"), 0.0);
  const h5::File waiting = h5::File::open(file("waiting.h5"), false);
  EXPECT_EQ(waiting.open_group("timeseries").read<double>("time"), (std::vector<double>{0.5}));
  EXPECT_EQ(waiting.open_group("timeseries").read<std::uint64_t>("events").size(), 1u);
  const h5::File at_once = h5::File::open(file("at_once.h5"), false);
  EXPECT_EQ(at_once.open_group("timeseries").read<double>("time"),
            (std::vector<double>{0.5, 1.0, 1.5}));
  EXPECT_EQ(at_once.open_group("timeseries").read<std::uint64_t>("events").size(), 3u);
}

// `carom resume` restarts from the last checkpoint, which may be older than the last rows and
// snapshots in the run file: those are written again, and the file ends up the same as the one
// of the run that was never interrupted.
TEST_F(OutputTest, ResumedRunRewritesTheOutputsAfterItsCheckpoint) {
  const GranularGasSpec spec = small_gas();
  auto add_outputs = [](EventDrivenEngine& sim, std::unique_ptr<RunFile>& run) {
    sim.add_periodic_action("sample", 0.0, 0.25, [&] { run->append_sample(sim); });
    sim.add_periodic_action("snapshot", 0.0, 0.5, [&] { run->write_snapshot(sim); });
  };
  {  // Never interrupted.
    EventDrivenEngine sim(make_granular_gas(spec));
    auto run = std::make_unique<RunFile>(file("straight.h5"), test_info(), sim.system());
    add_outputs(sim, run);
    sim.run_until(1.6);
  }
  {  // Checkpoint at 0.6, then outputs up to 1.1 and a crash.
    EventDrivenEngine sim(make_granular_gas(spec));
    auto run = std::make_unique<RunFile>(file("resumed.h5"), test_info(), sim.system());
    add_outputs(sim, run);
    sim.run_until(0.6);
    write_checkpoint(file("state.h5"), sim, test_info());
    sim.run_until(1.1);
  }
  {  // Resumed from the checkpoint.
    Checkpoint saved = read_checkpoint(file("state.h5"));
    EventDrivenEngine sim(make_granular_gas(spec), EventDrivenOptions{}, saved_engine_state(saved));
    auto run = RunFile::append(file("resumed.h5"));
    add_outputs(sim, run);
    sim.run_until(1.6);
  }
  const h5::File straight = h5::File::open(file("straight.h5"), false);
  const h5::File resumed = h5::File::open(file("resumed.h5"), false);
  const h5::Group a = straight.open_group("timeseries"), b = resumed.open_group("timeseries");
  EXPECT_EQ(a.read<double>("time").size(), 7u);
  for (const std::string& name : a.children()) {
    const h5::Dataset x = a.open_dataset(name), y = b.open_dataset(name);
    EXPECT_EQ(x.shape(), y.shape()) << name;
    const h5::Handle type(H5Dget_type(x.id()), H5Tclose);
    if (H5Tget_class(type.get()) == H5T_FLOAT)
      expect_same_bits(x.read<double>(), y.read<double>(), name);
    else
      expect_same_bits(x.read<std::uint64_t>(), y.read<std::uint64_t>(), name);
  }
  EXPECT_EQ(straight.open_group("snapshots").children(),
            resumed.open_group("snapshots").children());
  expect_same_bits(straight.read<double>("snapshots/000003/position"),
                   resumed.read<double>("snapshots/000003/position"), "last snapshot");
  EXPECT_EQ(check_xdmf(file("resumed.xmf"), file("resumed.h5")), 4u);
}

// ---- checkpoints ------------------------------------------------------------------------------

TEST_F(OutputTest, CheckpointRoundTripsEveryFieldBitForBit) {
  GranularGasSpec spec = small_gas();
  spec.fines_diameter_ratio = 0.5;
  spec.fines_number_fraction = 0.3;
  spec.volume_fraction = 0.2;
  EventDrivenEngine sim(make_granular_gas(spec));
  sim.add_periodic_action("sample", 0.1, 0.3, [] {});
  sim.add_periodic_action("checkpoint", 0.2, 1.0, [] {});
  sim.run_until(0.55);
  write_checkpoint(file("state.h5"), sim, test_info());
  EXPECT_FALSE(fs::exists(file("state.h5.tmp")));
  const Checkpoint back = read_checkpoint(file("state.h5"));
  EXPECT_EQ(back.info.scene_text, test_info().scene_text);
  EXPECT_EQ(back.info.scene_name, "test");
  EXPECT_EQ(back.info.seed, 42u);
  const EngineState back_state = saved_engine_state(back);
  expect_same_state(sim.state(), back_state);
  EXPECT_EQ(back_state.action_times.size(), 2u);
  EXPECT_GT(back_state.statistics.pair_events, 0u);
}

// Determinism across a checkpoint: run X goes straight to t2; run A stops at t1, writes a
// checkpoint and goes on (writing must not change it); run B is restored from that checkpoint
// (its System built again from the same spec) and runs to t2. All three end bit for bit equal.
TEST_F(OutputTest, RestoredRunContinuesBitForBit) {
  const GranularGasSpec spec = small_gas();
  const double t1 = 2.0, t2 = 6.0;
  int x_samples = 0, a_samples = 0, b_samples = 0;
  EventDrivenEngine x(make_granular_gas(spec));
  x.add_periodic_action("sample", 0.15, 0.3, [&] { ++x_samples; });
  x.run_until(t2);

  EventDrivenEngine a(make_granular_gas(spec));
  a.add_periodic_action("sample", 0.15, 0.3, [&] { ++a_samples; });
  a.run_until(t1);
  write_checkpoint(file("state.h5"), a, test_info());
  a.run_until(t2);

  Checkpoint saved = read_checkpoint(file("state.h5"));
  EventDrivenEngine b(make_granular_gas(spec), EventDrivenOptions{}, saved_engine_state(saved));
  b.add_periodic_action("sample", 0.0, 0.3, [&] { ++b_samples; });  // resumes at its saved time
  b.run_until(t2);

  expect_same_state(x.state(), a.state());
  expect_same_state(x.state(), b.state());
  EXPECT_EQ(a_samples, x_samples);
  EXPECT_EQ(b_samples, x_samples - 7) << "samples at 0.15, 0.45, ..., 1.95 came before t1";
  for (std::size_t i = 0; i < x.particle_count(); ++i)
    for (int c = 0; c < 3; ++c) EXPECT_EQ(bits(x.position(i)[c]), bits(b.position(i)[c]));
  EXPECT_GT(x.statistics().pair_events, 1000u) << "long enough to amplify any difference";
}

// A writer that died half-way leaves a partial `.tmp` beside the checkpoint: the checkpoint
// itself must still be the previous complete one, and the next write must succeed.
TEST_F(OutputTest, CrashedWriterNeverDestroysThePreviousCheckpoint) {
  EventDrivenEngine sim(make_granular_gas(small_gas()));
  sim.run_until(0.3);
  const std::string path = file("state.h5");
  write_checkpoint(path, sim, test_info());
  const EngineState first = sim.state();

  {  // The remains of a crashed writer: a truncated HDF5 file.
    std::ifstream in(path, std::ios::binary);
    std::string head(512, '\0');
    in.read(head.data(), 512);
    std::ofstream(path + ".tmp", std::ios::binary) << head;
  }
  expect_same_state(saved_engine_state(read_checkpoint(path)), first);

  // A writer that cannot even create its temporary file fails loudly and touches nothing.
  fs::remove(path + ".tmp");
  fs::create_directory(path + ".tmp");
  std::ofstream(path + ".tmp/keep") << "x";
  sim.run_until(0.6);
  try {
    write_checkpoint(path, sim, test_info());
    FAIL() << "writing over a directory must throw";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path + ".tmp"), std::string::npos) << e.what();
  }
  expect_same_state(saved_engine_state(read_checkpoint(path)), first);

  // Once the obstacle is gone, the next checkpoint replaces the old one.
  fs::remove_all(path + ".tmp");
  std::ofstream(path + ".tmp") << "leftover garbage";
  write_checkpoint(path, sim, test_info());
  expect_same_state(saved_engine_state(read_checkpoint(path)), sim.state());
  EXPECT_FALSE(fs::exists(path + ".tmp"));
}

TEST_F(OutputTest, ReadingABrokenCheckpointNamesTheFile) {
  std::ofstream(file("junk.h5")) << "not hdf5";
  try {
    read_checkpoint(file("junk.h5"));
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(file("junk.h5")), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace carom
