// The event-driven engine's state in HDF5 (checkpoints): written and read back exactly.
#include <string>
#include <vector>

#include "core/hdf5_arrays.hpp"
#include "events/event_driven/engine_state.hpp"
#include "events/statistics_io.hpp"

namespace carom {

using h5::flatten;
using h5::from_row_major;
using h5::row_major;
using h5::unflatten;

namespace {

/// One Event per particle as four parallel datasets: time, partner, partner_counter, kind.
void write_events(const h5::Group& group, const std::vector<Event>& list) {
  std::vector<double> time;
  std::vector<std::int32_t> partner;
  std::vector<std::uint32_t> partner_counter;
  std::vector<std::uint8_t> kind;
  for (const Event& e : list) {
    time.push_back(e.time);
    partner.push_back(e.partner);
    partner_counter.push_back(e.partner_counter);
    kind.push_back(static_cast<std::uint8_t>(e.kind));
  }
  group.write("time", time);
  group.write("partner", partner);
  group.write("partner_counter", partner_counter);
  group.write("kind", kind);
}

std::vector<Event> read_events(const h5::Group& group, hsize_t n) {
  const std::vector<double> time = group.read<double>("time", {n});
  const std::vector<std::int32_t> partner = group.read<std::int32_t>("partner", {n});
  const std::vector<std::uint32_t> counter = group.read<std::uint32_t>("partner_counter", {n});
  const std::vector<std::uint8_t> kind = group.read<std::uint8_t>("kind", {n});
  std::vector<Event> list(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (kind[i] > static_cast<std::uint8_t>(EventKind::CellCrossing))
      group.fail("kind[" + std::to_string(i) + "] is not an event kind");
    list[i] = Event{time[i], partner[i], counter[i], static_cast<EventKind>(kind[i])};
  }
  return list;
}

}  // namespace

void write_engine_state(const h5::Group& group, const EngineState& s) {
  group.set_attribute("method", std::string("event_driven"));
  const std::size_t n = s.particles.size();
  group.set_attribute("time", s.time);
  group.set_attribute("last_particle_event", s.last_particle_event);
  group.set_attribute("stall_window", s.stall_window);
  group.set_attribute("gas_work", s.gas_work);
  group.set_attribute("flow_energy", s.flow_energy);
  group.set_attribute("rate_start_pairs", s.rate_start_pairs);
  group.set_attribute("rate_start_walls", s.rate_start_walls);
  group.set_attribute("rate_start_time", s.rate_start_time);

  const ParticleStore& p = s.particles;
  const h5::Group particles = group.create_group("particles");
  particles.write("position", flatten(p.position), {n, 3});
  particles.write("velocity", flatten(p.velocity), {n, 3});
  particles.write("clock", p.clock);
  particles.write("radius", p.radius);
  particles.write("event_counter", s.event_counters);
  particles.write("spin", flatten(p.spin), {n, 3});
  particles.write("mass", p.mass);
  particles.write("inertia", p.inertia);
  particles.write("last_collision", s.last_collision);
  particles.write("species", p.species);
  particles.write("id", p.id);

  std::vector<std::int32_t> cells;
  for (const auto& c : s.cells) cells.insert(cells.end(), c.begin(), c.end());
  group.write("cells", cells, {n, 3});
  group.write("cell_list_places", s.places);

  write_events(group.create_group("events"), s.events);
  write_events(group.create_group("crossings"), s.crossings);
  std::vector<double> rate;
  std::vector<Vec3> drive;
  for (const RelaxFlight& f : s.flights) {
    rate.push_back(f.rate);
    drive.push_back(f.drive);
  }
  const h5::Group flights = group.create_group("flights");
  flights.write("rate", rate);
  flights.write("drive", flatten(drive), {drive.size(), 3});

  write_statistics(group.create_group("statistics"), s.statistics);

  group.write("stall_window_start", s.stall_window_start);
  group.write("stall_count", s.stall_count);

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

EngineState read_engine_state(const h5::Group& group) {
  if (group.has_attribute("method") && group.attribute<std::string>("method") != "event_driven")
    group.fail("holds the state of method '" + group.attribute<std::string>("method") +
               "', not of the event-driven engine");
  EngineState s;
  s.time = group.attribute<double>("time");
  s.last_particle_event = group.attribute<double>("last_particle_event");
  s.stall_window = group.attribute<double>("stall_window");
  // Checkpoints written before the gas work was booked: it starts from 0 there.
  if (group.has_attribute("gas_work")) s.gas_work = group.attribute<double>("gas_work");
  if (group.has_attribute("flow_energy")) s.flow_energy = group.attribute<double>("flow_energy");
  if (group.has_attribute("rate_start_time")) {  // later than the lasting-contact monitor
    s.rate_start_pairs = group.attribute<std::uint64_t>("rate_start_pairs");
    s.rate_start_walls = group.attribute<std::uint64_t>("rate_start_walls");
    s.rate_start_time = group.attribute<double>("rate_start_time");
  }

  ParticleStore& p = s.particles;
  const h5::Group particles = group.open_group("particles");
  const std::vector<hsize_t> shape = particles.open_dataset("position").shape();
  if (shape.size() != 2 || shape[1] != 3) particles.fail("position must have shape {N, 3}");
  const hsize_t n = shape[0];
  p.position = unflatten(particles.read<double>("position", {n, 3}));
  p.velocity = unflatten(particles.read<double>("velocity", {n, 3}));
  p.clock = particles.read<double>("clock", {n});
  p.radius = particles.read<double>("radius", {n});
  s.event_counters = particles.read<std::uint32_t>("event_counter", {n});
  p.spin = unflatten(particles.read<double>("spin", {n, 3}));
  p.mass = particles.read<double>("mass", {n});
  p.inertia = particles.read<double>("inertia", {n});
  s.last_collision = particles.read<double>("last_collision", {n});
  p.species = particles.read<std::uint32_t>("species", {n});
  p.id = particles.read<std::uint64_t>("id", {n});

  const std::vector<std::int32_t> cells = group.read<std::int32_t>("cells", {n, 3});
  s.cells.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    s.cells[i] = {cells[3 * i], cells[3 * i + 1], cells[3 * i + 2]};
  if (group.contains("cell_list_places"))
    s.places = group.read<std::int32_t>("cell_list_places", {n});

  s.events = read_events(group.open_group("events"), n);
  s.crossings = read_events(group.open_group("crossings"), n);
  const h5::Group flights = group.open_group("flights");
  const std::vector<double> rate = flights.read<double>("rate", {n});
  const std::vector<Vec3> drive = unflatten(flights.read<double>("drive", {n, 3}));
  s.flights.resize(n);
  for (std::size_t i = 0; i < n; ++i) s.flights[i] = RelaxFlight{rate[i], drive[i]};

  s.statistics = read_statistics(group.open_group("statistics"));

  s.stall_window_start = group.read<double>("stall_window_start", {n});
  s.stall_count = group.read<std::uint32_t>("stall_count", {n});

  const h5::Group actions = group.open_group("actions");
  const std::vector<std::string> names = actions.read_strings("name");
  const std::vector<double> next_time = actions.read<double>("next_time", {names.size()});
  for (std::size_t k = 0; k < names.size(); ++k)
    s.action_times.emplace_back(names[k], next_time[k]);
  return s;
}


}  // namespace carom
