// The Monte Carlo engine's state in HDF5 (checkpoints): written and read back exactly.
#include <string>
#include <vector>

#include "core/hdf5_arrays.hpp"
#include "events/monte_carlo/engine.hpp"
#include "events/statistics_io.hpp"

namespace carom {

using h5::flatten;
using h5::from_row_major;
using h5::row_major;
using h5::unflatten;

// Layout (doubles as native doubles: bit for bit): attributes method = "monte_carlo", time,
// step_start, step_end, time_step, cell_size, max_collisions_per_step, bound_exceeded,
// gas_work (J, at step_start), flow_energy (J);
// rng (the generator's text state); particles/ (position, velocity, spin (N x 3), clock,
// radius, mass, inertia, species, id) as of step_start; flights/ (rate, drive (N x 3));
// statistics/ as every method writes it (write_statistics), plus travelling_collisions and
// travelling_impacts (S x S);
// actions/ (name, next_time).
void write_monte_carlo_state(const h5::Group& group, const MonteCarloState& s) {
  group.set_attribute("method", std::string("monte_carlo"));
  group.set_attribute("time", s.time);
  group.set_attribute("step_start", s.step_start);
  group.set_attribute("step_end", s.step_end);
  group.set_attribute("time_step", s.time_step);
  group.set_attribute("cell_size", s.cell_size);
  group.set_attribute("max_collisions_per_step", s.max_collisions_per_step);
  group.set_attribute("bound_exceeded", s.bound_exceeded);
  group.set_attribute("gas_work", s.gas_work);
  group.set_attribute("flow_energy", s.flow_energy);
  group.write_string("rng", s.rng);

  const std::size_t n = s.particles.size();
  const ParticleStore& p = s.particles;
  const h5::Group particles = group.create_group("particles");
  particles.write("position", flatten(p.position), {n, 3});
  particles.write("velocity", flatten(p.velocity), {n, 3});
  particles.write("spin", flatten(p.spin), {n, 3});
  particles.write("clock", p.clock);
  particles.write("radius", p.radius);
  particles.write("mass", p.mass);
  particles.write("inertia", p.inertia);
  particles.write("species", p.species);
  particles.write("id", p.id);

  std::vector<double> rate;
  std::vector<Vec3> drive;
  for (const RelaxFlight& f : s.flights) {
    rate.push_back(f.rate);
    drive.push_back(f.drive);
  }
  const h5::Group flights = group.create_group("flights");
  flights.write("rate", rate);
  flights.write("drive", flatten(drive), {drive.size(), 3});

  const h5::Group stats = group.create_group("statistics");
  write_statistics(stats, s.statistics);
  stats.write("travelling_collisions", s.travelling.collisions);
  stats.write("travelling_impacts", s.travelling.impacts);

  const h5::Group actions = group.create_group("actions");
  std::vector<std::string> names;
  std::vector<double> next_time;
  for (const auto& [name, t] : s.action_times) {
    names.push_back(name);
    next_time.push_back(t);
  }
  actions.write_strings("name", names);
  actions.write("next_time", next_time);
}

MonteCarloState read_monte_carlo_state(const h5::Group& group) {
  if (!group.has_attribute("method") || group.attribute<std::string>("method") != "monte_carlo")
    group.fail("does not hold the state of the Monte Carlo method");
  MonteCarloState s;
  s.time = group.attribute<double>("time");
  s.step_start = group.attribute<double>("step_start");
  s.step_end = group.attribute<double>("step_end");
  s.time_step = group.attribute<double>("time_step");
  s.cell_size = group.attribute<double>("cell_size");
  s.max_collisions_per_step = group.attribute<double>("max_collisions_per_step");
  s.bound_exceeded = group.attribute<std::uint64_t>("bound_exceeded");
  // Checkpoints written before the gas work was booked: it starts from 0 there.
  if (group.has_attribute("gas_work")) s.gas_work = group.attribute<double>("gas_work");
  if (group.has_attribute("flow_energy")) s.flow_energy = group.attribute<double>("flow_energy");
  s.rng = group.read_string("rng");

  ParticleStore& p = s.particles;
  const h5::Group particles = group.open_group("particles");
  const std::vector<hsize_t> shape = particles.open_dataset("position").shape();
  if (shape.size() != 2 || shape[1] != 3) particles.fail("position must have shape {N, 3}");
  const hsize_t n = shape[0];
  p.position = unflatten(particles.read<double>("position", {n, 3}));
  p.velocity = unflatten(particles.read<double>("velocity", {n, 3}));
  p.spin = unflatten(particles.read<double>("spin", {n, 3}));
  p.clock = particles.read<double>("clock", {n});
  p.radius = particles.read<double>("radius", {n});
  p.mass = particles.read<double>("mass", {n});
  p.inertia = particles.read<double>("inertia", {n});
  p.species = particles.read<std::uint32_t>("species", {n});
  p.id = particles.read<std::uint64_t>("id", {n});

  const h5::Group flights = group.open_group("flights");
  const std::vector<double> rate = flights.read<double>("rate", {n});
  const std::vector<Vec3> drive = unflatten(flights.read<double>("drive", {n, 3}));
  s.flights.resize(n);
  for (std::size_t i = 0; i < n; ++i) s.flights[i] = RelaxFlight{rate[i], drive[i]};

  const h5::Group stats = group.open_group("statistics");
  s.statistics = read_statistics(stats);
  const std::size_t species = s.statistics.species_count;
  s.travelling.collisions = stats.read<std::uint64_t>("travelling_collisions", {species * species});
  s.travelling.impacts = stats.read<std::uint64_t>("travelling_impacts", {species * species});

  const h5::Group actions = group.open_group("actions");
  const std::vector<std::string> names = actions.read_strings("name");
  const std::vector<double> next_time = actions.read<double>("next_time", {names.size()});
  for (std::size_t k = 0; k < names.size(); ++k) s.action_times.emplace_back(names[k], next_time[k]);
  return s;
}

}  // namespace carom
