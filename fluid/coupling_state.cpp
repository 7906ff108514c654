// The coupling's checkpoint (GasCoupling::save and restore, fluid/coupling.hpp): every array
// the next fluid step and the outputs after it depend on, each under its own name in one HDF5
// group, read back with its shape checked against the scene's grid and species.
//
// Layout of the group. Arrays over cells or faces have the HDF5 shape (n_z, n_y, n_x), x
// fastest, with n the counts of cells, or of the faces of one axis (n_a + 1 faces along their own
// axis a, n_a on a periodic axis). S is the number of species. Doubles are native doubles.
//   face_velocity_x, _y, _z  faces of x, y, z  interstitial gas velocity normal to the face, m/s
//   inlet_drop_x, _y, _z     faces of x, y, z  face minus cell-centre pressure on inlet faces
//                                               (0 elsewhere), Pa: GasSolver::inlet_drop
//   pressure                 cells             gas pressure, Pa
//   previous_porosity        cells             porosity of the last gas step, the old one of the
//                                               next (absent before the first step)
//   porosity                 cells             porosity of the last particle mapping
//   sauter_diameter          cells             Sauter mean diameter of the last mapping, m (0
//                                               where the closure does not read it)
//   species_count            (S) uint64        particles per species at the last step
//   species_gas_velocity     (S, 3)            sum over the species' particles of u_i, m/s
//   species_gas_force        (S, 3)            sum of K_i (u_i - v_i) - V_i grad p_i, N
//   species_porosity         (S)               sum of eps_i
//   total_drag               (3)               sum of the drag forces on the particles, N
//   fluid_steps              (1) uint64        fluid steps taken (CouplingTimes::steps)
//   unconverged_steps        (1) uint64        of which SIMPLE hit its iteration limit
//   wall_seconds             (3)               CouplingTimes mapping, solve, interpolation, s
//   particle_gas_velocity    (N, 3)            u_i at each of the N particles at the last step,
//                                               m/s, in the method's particle order: the spin
//                                               forces' kicks read it (only with spin forces on)
// The per-particle cell weights are not stored: each step maps the particles afresh.
#include <cstdint>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include "core/hdf5.hpp"
#include "coupling.hpp"

namespace carom {

namespace {

const std::array<std::string, 3> kAxes{"x", "y", "z"};

/// HDF5 shape (n_z, n_y, n_x) of an array laid out like the gas cells, x fastest.
std::vector<hsize_t> zyx_shape(const std::array<int, 3>& counts) {
  return {static_cast<hsize_t>(counts[2]), static_cast<hsize_t>(counts[1]),
          static_cast<hsize_t>(counts[0])};
}

/// Dataset `name` of `group` as T, after checking that it exists, has shape `shape` and is
/// stored as T's kind of number at T's size (so that doubles come back bit for bit). `fits`
/// says what the shape follows from. Throws std::invalid_argument.
template <class T>
std::vector<T> read_exactly(const h5::Group& group, const std::string& name,
                            const std::vector<hsize_t>& shape, const std::string& fits) {
  const std::string parent = group.object_path() == "/" ? "" : group.object_path();
  const std::string where = group.file_path() + ":" + parent + "/" + name;
  const std::string expected = "expected shape " + h5::Group::describe(shape) + ", " + fits;
  if (!group.contains(name))
    throw std::invalid_argument(where + ": missing from the gas checkpoint (" + expected + ")");
  const h5::Dataset data = group.open_dataset(name);
  if (data.shape() != shape)
    throw std::invalid_argument(where + ": shape " + h5::Group::describe(data.shape()) +
                                " does not fit the scene; " + expected);
  const h5::Handle type(H5Dget_type(data.id()), H5Tclose);
  const H5T_class_t number_class = std::is_floating_point_v<T> ? H5T_FLOAT : H5T_INTEGER;
  if (!type.valid() || H5Tget_class(type.get()) != number_class ||
      H5Tget_size(type.get()) != sizeof(T))
    throw std::invalid_argument(
        where + ": not stored as " +
        (std::is_floating_point_v<T> ? "8-byte floating-point numbers" : "8-byte integers") +
        ", so it cannot be restored exactly");
  return data.read<T>();
}

}  // namespace

void GasCoupling::save(const h5::Group& group) const {
  const GasSolverState gas = solver_->state();
  const std::vector<hsize_t> cells = zyx_shape(settings_.cells);
  for (int a = 0; a < 3; ++a) {
    const std::vector<hsize_t> faces = zyx_shape(solver_->face_counts(a));
    group.write("face_velocity_" + kAxes[a], gas.face_velocity[a], faces);
    group.write("inlet_drop_" + kAxes[a], gas.inlet_drop[a], faces);
  }
  group.write("pressure", gas.pressure, cells);
  if (!gas.previous_porosity.empty())
    group.write("previous_porosity", gas.previous_porosity, cells);
  group.write("porosity", porosity_, cells);
  group.write("sauter_diameter", sauter_, cells);
  // What the last step's flights were set from, per species and in total, so that outputs after
  // a restore read what they would have read (zeros before the first step).
  const std::size_t species = species_density_.size();
  std::vector<std::uint64_t> count(species, 0);
  std::vector<double> velocity(3 * species, 0.0), force(3 * species, 0.0), porosity(species, 0.0);
  for (std::size_t s = 0; s < species && s < species_count_.size(); ++s) {
    count[s] = species_count_[s];
    for (int k = 0; k < 3; ++k) {
      velocity[3 * s + k] = species_gas_velocity_[s][k];
      force[3 * s + k] = species_gas_force_[s][k];
    }
    porosity[s] = species_porosity_[s];
  }
  group.write("species_count", count);
  group.write("species_gas_velocity", velocity, {species, 3});
  group.write("species_gas_force", force, {species, 3});
  group.write("species_porosity", porosity);
  group.write<double>("total_drag", {total_drag_.x(), total_drag_.y(), total_drag_.z()});
  group.write<std::uint64_t>("fluid_steps", {times_.steps});
  group.write<std::uint64_t>("unconverged_steps", {times_.unconverged_steps});
  group.write<double>("wall_seconds", {times_.mapping, times_.solve, times_.interpolation});
  if (settings_.spin_forces.any()) {
    std::vector<double> u(3 * particle_gas_velocity_.size());
    for (std::size_t i = 0; i < particle_gas_velocity_.size(); ++i)
      for (int k = 0; k < 3; ++k) u[3 * i + k] = particle_gas_velocity_[i][k];
    group.write("particle_gas_velocity", u, {particle_gas_velocity_.size(), 3});
  }
}

void GasCoupling::restore(const h5::Group& group) {
  const auto& n = settings_.cells;
  const std::string grid = "the scene's gas grid of " + std::to_string(n[0]) + " x " +
                           std::to_string(n[1]) + " x " + std::to_string(n[2]) +
                           " cells (x, y, z), stored as (z, y, x)";
  const std::string per_cell = "one value per cell of " + grid;
  const std::vector<hsize_t> cells = zyx_shape(n);
  GasSolverState gas;
  for (int a = 0; a < 3; ++a) {
    const std::vector<hsize_t> faces = zyx_shape(solver_->face_counts(a));
    const std::string per_face = "one value per " + kAxes[a] + " face of " + grid;
    gas.face_velocity[a] =
        read_exactly<double>(group, "face_velocity_" + kAxes[a], faces, per_face);
    gas.inlet_drop[a] = read_exactly<double>(group, "inlet_drop_" + kAxes[a], faces, per_face);
  }
  gas.pressure = read_exactly<double>(group, "pressure", cells, per_cell);
  if (group.contains("previous_porosity"))
    gas.previous_porosity = read_exactly<double>(group, "previous_porosity", cells, per_cell);
  std::vector<double> porosity = read_exactly<double>(group, "porosity", cells, per_cell);
  std::vector<double> sauter = read_exactly<double>(group, "sauter_diameter", cells, per_cell);

  const std::size_t species = species_density_.size();
  const std::string per_species =
      "one row per species of the scene (" + std::to_string(species) + ")";
  const std::vector<std::uint64_t> count =
      read_exactly<std::uint64_t>(group, "species_count", {species}, per_species);
  const std::vector<double> velocity =
      read_exactly<double>(group, "species_gas_velocity", {species, 3}, per_species);
  const std::vector<double> force =
      read_exactly<double>(group, "species_gas_force", {species, 3}, per_species);
  std::vector<double> species_porosity =
      read_exactly<double>(group, "species_porosity", {species}, per_species);
  const std::vector<double> drag = read_exactly<double>(group, "total_drag", {3}, "x, y, z");
  const std::vector<std::uint64_t> steps =
      read_exactly<std::uint64_t>(group, "fluid_steps", {1}, "one count");
  const std::vector<std::uint64_t> unconverged =
      read_exactly<std::uint64_t>(group, "unconverged_steps", {1}, "one count");
  const std::vector<double> seconds =
      read_exactly<double>(group, "wall_seconds", {3}, "mapping, solve, interpolation");
  std::vector<Vec3> particle_u;
  if (settings_.spin_forces.any()) {
    const std::string name = "particle_gas_velocity";
    const hsize_t rows = group.contains(name) && !group.open_dataset(name).shape().empty()
                             ? group.open_dataset(name).shape()[0]
                             : 0;
    const std::vector<double> u = read_exactly<double>(
        group, name, {rows, 3}, "one row per particle (the scene's spin forces need it)");
    particle_u.resize(rows);
    for (std::size_t i = 0; i < rows; ++i) particle_u[i] = Vec3(u[3 * i], u[3 * i + 1], u[3 * i + 2]);
  }

  // Everything is read and checked: only now does the state change.
  solver_->set_state(std::move(gas));
  porosity_ = std::move(porosity);
  sauter_ = std::move(sauter);
  species_count_.assign(count.begin(), count.end());
  species_gas_velocity_.resize(species);
  species_gas_force_.resize(species);
  for (std::size_t s = 0; s < species; ++s) {
    species_gas_velocity_[s] = Vec3(velocity[3 * s], velocity[3 * s + 1], velocity[3 * s + 2]);
    species_gas_force_[s] = Vec3(force[3 * s], force[3 * s + 1], force[3 * s + 2]);
  }
  species_porosity_ = std::move(species_porosity);
  total_drag_ = Vec3(drag[0], drag[1], drag[2]);
  times_.steps = steps[0];
  times_.unconverged_steps = unconverged[0];
  times_.mapping = seconds[0];
  times_.solve = seconds[1];
  times_.interpolation = seconds[2];
  particle_gas_velocity_ = std::move(particle_u);
}

}  // namespace carom
