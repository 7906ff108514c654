// The soft-sphere method's state in HDF5 (checkpoints): everything that changes during a run,
// written and read back bit for bit; the scene supplies the rest (species, walls, laws,
// options), and the contact constants are derived from it again, identically.
#include <string>
#include <vector>

#include "core/hdf5_arrays.hpp"
#include "events/soft_sphere/engine.hpp"
#include "events/statistics_io.hpp"

namespace carom {

using h5::flatten;
using h5::unflatten;

void SoftSphereEngine::save_state(const h5::Group& group) const {
  group.set_attribute("method", std::string(kind()));
  group.set_attribute("time", time_);
  group.set_attribute("steps", steps_);
  group.set_attribute("impact_speed", impact_speed_);
  group.set_attribute("elastic", elastic_);
  group.set_attribute("gas_work", gas_work_);
  group.set_attribute("flow_energy", flow_energy_);
  group.set_attribute("gas_forces", static_cast<std::uint8_t>(gas_forces_ ? 1 : 0));
  group.set_attribute("travelled", travelled_);
  group.set_attribute("energy_start", energy_start_);
  group.set_attribute("energy_scale", energy_scale_);
  group.set_attribute("worst_overlap", worst_overlap_);
  group.set_attribute("neighbour_list_builds", list_.builds());
  const ParticleStore& p = system_.particles;
  const std::size_t n = p.size();
  const h5::Group particles = group.create_group("particles");
  particles.write("position", flatten(p.position), {n, 3});
  particles.write("velocity", flatten(p.velocity), {n, 3});
  particles.write("spin", flatten(p.spin), {n, 3});
  particles.write("radius", p.radius);
  particles.write("mass", p.mass);
  particles.write("inertia", p.inertia);
  particles.write("species", p.species);
  particles.write("id", p.id);
  particles.write("contact_force", flatten(force_), {n, 3});
  particles.write("contact_torque", flatten(torque_), {n, 3});
  std::vector<double> rate;
  std::vector<Vec3> drive;
  for (const RelaxFlight& f : flights_) {
    rate.push_back(f.rate);
    drive.push_back(f.drive);
  }
  particles.write("flight_rate", rate);
  particles.write("flight_drive", flatten(drive), {n, 3});

  const h5::Group list = group.create_group("neighbour_list");
  list.write("reference_position", flatten(list_.reference_positions()),
             {list_.reference_positions().size(), 3});
  auto write_contacts = [](const h5::Group& g, const auto& contacts) {
    std::vector<std::int32_t> first, second;
    std::vector<std::uint8_t> touching;
    std::vector<double> since, overlap;
    std::vector<Vec3> spring;
    for (const auto& c : contacts) {
      if constexpr (requires { c.owner; }) {
        first.push_back(c.owner);
        second.push_back(c.partner);
      } else {
        first.push_back(c.particle);
        second.push_back(c.wall);
      }
      touching.push_back(c.touching ? 1 : 0);
      since.push_back(c.since);
      overlap.push_back(c.overlap);
      spring.push_back(c.spring);
    }
    g.write("first", first);
    g.write("second", second);
    g.write("touching", touching);
    g.write("since", since);
    g.write("overlap", overlap);
    g.write("spring", flatten(spring), {spring.size(), 3});
  };
  write_contacts(list.create_group("pairs"), list_.pairs());
  write_contacts(list.create_group("walls"), list_.wall_pairs());

  write_statistics(group.create_group("statistics"), statistics_);
  const h5::Group durations = group.create_group("contact_durations");
  durations.write("count", durations_.count);
  durations.write("total", durations_.total);

  const h5::Group actions = group.create_group("actions");
  std::vector<std::string> names;
  std::vector<double> next_time;
  for (const SteppedAction& a : actions_) {
    names.push_back(a.name);
    next_time.push_back(a.next_time);
  }
  actions.write_strings("name", names);
  actions.write("next_time", next_time);
}

SoftSphereEngine::SoftSphereEngine(System system, SoftSphereOptions options, const h5::Group& saved)
    : system_(std::move(system)), options_(std::move(options)), list_(system_.domain, 0.0) {
  const h5::Group particles = saved.open_group("particles");
  const std::vector<std::uint64_t> id = particles.read<std::uint64_t>("id");
  const hsize_t n = id.size();
  ParticleStore& p = system_.particles;
  p = ParticleStore{};
  p.position = unflatten(particles.read<double>("position", {n, 3}));
  p.velocity = unflatten(particles.read<double>("velocity", {n, 3}));
  p.spin = unflatten(particles.read<double>("spin", {n, 3}));
  p.radius = particles.read<double>("radius", {n});
  p.mass = particles.read<double>("mass", {n});
  p.inertia = particles.read<double>("inertia", {n});
  p.species = particles.read<std::uint32_t>("species", {n});
  p.id = id;
  for (std::uint32_t s : p.species)
    if (s >= system_.species.size()) particles.fail("a species index is beyond the scene's species");
  // The contact constants and the step from the scene, at the saved run's impact speed (its
  // default depends on the velocities at the start): the same as the saved run's.
  options_.impact_speed = saved.attribute<double>("impact_speed");
  setup();
  time_ = saved.attribute<double>("time");
  p.clock.assign(n, time_);
  steps_ = saved.attribute<std::uint64_t>("steps");
  elastic_ = saved.attribute<double>("elastic");
  gas_work_ = saved.attribute<double>("gas_work");
  if (saved.has_attribute("flow_energy")) flow_energy_ = saved.attribute<double>("flow_energy");
  gas_forces_ = saved.attribute<std::uint8_t>("gas_forces") != 0;
  travelled_ = saved.attribute<double>("travelled");
  energy_start_ = saved.attribute<double>("energy_start");
  energy_scale_ = saved.attribute<double>("energy_scale");
  worst_overlap_ = saved.attribute<double>("worst_overlap");
  force_ = unflatten(particles.read<double>("contact_force", {n, 3}));
  torque_ = unflatten(particles.read<double>("contact_torque", {n, 3}));
  const std::vector<double> rate = particles.read<double>("flight_rate", {n});
  const std::vector<Vec3> drive = unflatten(particles.read<double>("flight_drive", {n, 3}));
  flights_.resize(n);
  for (std::size_t i = 0; i < n; ++i) flights_[i] = RelaxFlight{rate[i], drive[i]};

  const h5::Group list = saved.open_group("neighbour_list");
  std::vector<Vec3> reference = unflatten(list.read<double>("reference_position", {n, 3}));
  auto read_contacts = [&](const h5::Group& g, auto& out) {
    const std::vector<std::int32_t> first = g.read<std::int32_t>("first");
    const hsize_t m = first.size();
    const std::vector<std::int32_t> second = g.read<std::int32_t>("second", {m});
    const std::vector<std::uint8_t> touching = g.read<std::uint8_t>("touching", {m});
    const std::vector<double> since = g.read<double>("since", {m});
    const std::vector<double> overlap = g.read<double>("overlap", {m});
    const std::vector<Vec3> spring = unflatten(g.read<double>("spring", {m, 3}));
    out.resize(m);
    for (std::size_t k = 0; k < m; ++k) {
      auto& c = out[k];
      if constexpr (requires { c.owner; }) {
        c.owner = first[k];
        c.partner = second[k];
        if (first[k] < 0 || second[k] < 0 || static_cast<hsize_t>(std::max(first[k], second[k])) >= n)
          g.fail("a listed pair names a particle beyond the saved ones");
      } else {
        c.particle = first[k];
        c.wall = second[k];
        if (first[k] < 0 || static_cast<hsize_t>(first[k]) >= n || second[k] < 0 ||
            static_cast<std::size_t>(second[k]) >= system_.walls.size())
          g.fail("a listed wall contact names a particle or wall that does not exist");
      }
      c.touching = touching[k] != 0;
      c.since = since[k];
      c.overlap = overlap[k];
      c.spring = spring[k];
    }
  };
  std::vector<PairContactState> pairs;
  std::vector<WallContactState> walls;
  read_contacts(list.open_group("pairs"), pairs);
  read_contacts(list.open_group("walls"), walls);
  list_.restore(std::move(reference), std::move(pairs), std::move(walls));
  list_.set_builds(saved.attribute<std::uint64_t>("neighbour_list_builds"));

  statistics_ = read_statistics(saved.open_group("statistics"));
  if (statistics_.species_count != system_.species.size() || statistics_.wall_count != system_.walls.size())
    saved.fail("its counters are for another number of species or walls than the scene's");
  const h5::Group durations = saved.open_group("contact_durations");
  const std::size_t S = system_.species.size();
  durations_.count = durations.read<std::uint64_t>("count", {S * S});
  durations_.total = durations.read<double>("total", {S * S});

  const h5::Group actions = saved.open_group("actions");
  const std::vector<std::string> names = actions.read_strings("name");
  const std::vector<double> next_time = actions.read<double>("next_time", {names.size()});
  for (std::size_t k = 0; k < names.size(); ++k) restored_action_times_.emplace_back(names[k], next_time[k]);
}

}  // namespace carom
