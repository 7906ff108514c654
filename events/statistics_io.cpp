#include "events/statistics_io.hpp"

#include "core/hdf5_arrays.hpp"

namespace carom {

using h5::flatten;
using h5::from_row_major;
using h5::row_major;
using h5::unflatten;

void write_statistics(const h5::Group& stats, const RunStatistics& st) {
  stats.set_attribute("species_count", static_cast<std::uint64_t>(st.species_count));
  stats.set_attribute("wall_count", static_cast<std::uint64_t>(st.wall_count));
  stats.set_attribute("dissipated_energy", st.dissipated_energy);
  stats.set_attribute("events", st.events);
  stats.set_attribute("invalid_events", st.invalid_events);
  stats.set_attribute("pair_events", st.pair_events);
  stats.set_attribute("wall_events", st.wall_events);
  stats.set_attribute("cell_crossings", st.cell_crossings);
  stats.write("pair_collisions", st.pair_collisions);
  stats.write("wall_collisions", st.wall_collisions);
  stats.write("pair_impacts", st.pair_impacts);
  stats.write("wall_impacts", st.wall_impacts);
  stats.write("pair_impulse", st.pair_impulse);
  stats.write("wall_impulse",
              flatten(std::vector<Vec3>(st.wall_impulse.begin(), st.wall_impulse.end())),
              {st.wall_impulse.size(), 3});
  stats.write("virial", row_major(st.virial), {3, 3});
  write_tagged(stats, st.tagged);
}

void write_tagged(const h5::Group& stats, const TaggedImpulses& tagged) {
  if (tagged.ids.empty()) return;
  const h5::Group group = stats.create_group("tagged");
  group.set_attribute("species_count", static_cast<std::uint64_t>(tagged.species_count));
  group.set_attribute("wall_count", static_cast<std::uint64_t>(tagged.wall_count));
  group.write("id", tagged.ids);
  group.write("impulse", flatten(tagged.impulse), {tagged.impulse.size(), 3});
  group.write("step_force", flatten(tagged.step_force), {tagged.step_force.size(), 3});
}

TaggedImpulses read_tagged(const h5::Group& stats) {
  TaggedImpulses tagged;
  if (!stats.contains("tagged")) return tagged;
  const h5::Group group = stats.open_group("tagged");
  tagged.species_count = group.attribute<std::uint64_t>("species_count");
  tagged.wall_count = group.attribute<std::uint64_t>("wall_count");
  tagged.ids = group.read<std::uint64_t>("id");
  const std::size_t entries = tagged.ids.size() * tagged.partners();
  tagged.impulse = unflatten(group.read<double>("impulse", {entries, 3}));
  tagged.step_force = unflatten(group.read<double>("step_force", {entries, 3}));
  return tagged;
}

RunStatistics read_statistics(const h5::Group& stats) {
  RunStatistics st;
  const auto species = stats.attribute<std::uint64_t>("species_count");
  const auto walls = stats.attribute<std::uint64_t>("wall_count");
  st.resize(species, walls);
  st.dissipated_energy = stats.attribute<double>("dissipated_energy");
  st.events = stats.attribute<std::uint64_t>("events");
  st.invalid_events = stats.attribute<std::uint64_t>("invalid_events");
  st.pair_events = stats.attribute<std::uint64_t>("pair_events");
  st.wall_events = stats.attribute<std::uint64_t>("wall_events");
  st.cell_crossings = stats.attribute<std::uint64_t>("cell_crossings");
  st.pair_collisions = stats.read<std::uint64_t>("pair_collisions", {species * species});
  st.wall_collisions = stats.read<std::uint64_t>("wall_collisions", {species * walls});
  st.pair_impacts = stats.read<std::uint64_t>("pair_impacts", {species * species});
  st.wall_impacts = stats.read<std::uint64_t>("wall_impacts", {species * walls});
  st.pair_impulse = stats.read<double>("pair_impulse", {species * species});
  const std::vector<Vec3> impulse = unflatten(stats.read<double>("wall_impulse", {walls, 3}));
  st.wall_impulse.assign(impulse.begin(), impulse.end());
  st.virial = from_row_major(stats.read<double>("virial", {3, 3}));
  st.tagged = read_tagged(stats);
  return st;
}

}  // namespace carom
