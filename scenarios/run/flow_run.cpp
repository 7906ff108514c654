#include "scenarios/run/flow_run.hpp"

#include <cmath>
#include <sstream>

#include "scenarios/run/summary.hpp"

namespace carom {

std::unique_ptr<FlowBoundaries> attach_flow(CollisionMethod& sim, const Scene& scene,
                                            const h5::Group* saved_state) {
  if (!scene.flow.any()) return nullptr;
  auto flow = std::make_unique<FlowBoundaries>(scene.flow.inflows, scene.flow.outflows, sim.system(),
                                               scene.seed, sim.time(), scene.flow.interval);
  if (saved_state != nullptr) flow->restore(*saved_state);
  FlowBoundaries* boundaries = flow.get();
  sim.add_synchronising_action("flow_step", sim.time(), scene.flow.interval, [boundaries](GlobalStep& step) {
    boundaries->step(step.time, step.particles, step.change);
  });
  return flow;
}

void append_flow_series(const FlowBoundaries& flow, const CollisionMethod& sim, SeriesRow& row) {
  const std::size_t S = sim.system().species.size();
  std::vector<double> present(S, 0.0);
  for (std::uint32_t s : sim.system().particles.species) present[s] += 1.0;
  row.push_back({"particles_present", S, present});
  row.push_back({"particle_seconds", S, flow.particle_seconds_at(sim.time())});
  std::vector<double> entered, entered_mass, waiting, left, left_mass;
  for (std::size_t k = 0; k < flow.inflows().size(); ++k) {
    const InflowCounters& c = flow.inflow_counters(k);
    entered.push_back(static_cast<double>(c.entered));
    entered_mass.push_back(c.entered_mass);
    waiting.push_back(static_cast<double>(c.waiting()));
  }
  for (std::size_t k = 0; k < flow.outflows().size(); ++k) {
    left.push_back(static_cast<double>(flow.outflow_counters(k).left));
    left_mass.push_back(flow.outflow_counters(k).left_mass);
  }
  const std::size_t I = flow.inflows().size(), O = flow.outflows().size();
  if (I > 0) {
    row.push_back({"entered", I, entered});
    row.push_back({"entered_mass", I, entered_mass});
    row.push_back({"waiting", I, waiting});
  }
  if (O > 0) {
    row.push_back({"left", O, left});
    row.push_back({"left_mass", O, left_mass});
  }
  row.push_back({"flow_energy", 0, {sim.energies().flow}});
}

FlowStart flow_start(const FlowBoundaries& flow, double time) {
  FlowStart s;
  s.last_step = flow.last_time();
  s.particle_seconds = flow.particle_seconds_at(time);
  for (std::size_t k = 0; k < flow.inflows().size(); ++k) {
    s.entered_mass.push_back(flow.inflow_counters(k).entered_mass);
    s.entered.push_back(flow.inflow_counters(k).entered);
  }
  for (std::size_t k = 0; k < flow.outflows().size(); ++k) {
    s.left_mass.push_back(flow.outflow_counters(k).left_mass);
    s.left.push_back(flow.outflow_counters(k).left);
  }
  return s;
}

std::string flow_summary_json(const FlowBoundaries& flow, const FlowStart& start, double start_time,
                              double time) {
  const double span = time - start_time;
  auto rate = [&](double mass) { return span > 0 ? mass / span : NAN; };
  // Inflows place what they owe at each flow step: their rate is measured between steps.
  const double steps = flow.last_time() - start.last_step;
  auto placed_rate = [&](double mass) { return steps > 0 ? mass / steps : NAN; };
  std::ostringstream j;
  j << "{\"inflows\": [";
  for (std::size_t k = 0; k < flow.inflows().size(); ++k) {
    const Inflow& in = flow.inflows()[k];
    const InflowCounters& c = flow.inflow_counters(k);
    j << (k ? ", " : "") << "{\"name\": " << json_string(in.name)
      << ", \"set_mass_flow\": " << json_number(in.mass_flow)
      << ", \"mass_flow\": " << json_number(placed_rate(c.entered_mass - start.entered_mass[k]))
      << ", \"mass_flow_resolution\": "
      << json_number(
             placed_rate(c.entered > 0 ? c.entered_mass / static_cast<double>(c.entered) : NAN))
      << ", \"entered\": " << (c.entered - start.entered[k]) << ", \"waiting\": " << c.waiting()
      << ", \"blocked_steps\": " << c.blocked_steps
      << ", \"blocked_message\": " << json_string(flow.blocked_message(k)) << "}";
  }
  j << "], \"outflows\": [";
  for (std::size_t k = 0; k < flow.outflows().size(); ++k) {
    const OutflowCounters& c = flow.outflow_counters(k);
    j << (k ? ", " : "") << "{\"name\": " << json_string(flow.outflows()[k].name)
      << ", \"mass_flow\": " << json_number(rate(c.left_mass - start.left_mass[k]))
      << ", \"left\": " << (c.left - start.left[k]) << "}";
  }
  j << "], \"mean_particles_present\": [";
  const std::vector<double> now = flow.particle_seconds_at(time);
  for (std::size_t s = 0; s < now.size(); ++s)
    j << (s ? ", " : "") << json_number(span > 0 ? (now[s] - start.particle_seconds[s]) / span : NAN);
  j << "]}";
  return j.str();
}

}  // namespace carom
