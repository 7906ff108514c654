#pragma once
/// The inflows and outflows of a scene wired into a run (events/flow/): the flow step as a
/// synchronising global event, its series in the time series, its part of summary.json, its
/// state in checkpoints.
#include <memory>
#include <string>
#include <vector>

#include "core/hdf5.hpp"
#include "events/flow/flow_boundaries.hpp"
#include "events/method.hpp"
#include "scenarios/analysis/run_analysis.hpp"
#include "scenarios/scene/scene.hpp"

namespace carom {

/// Builds the scene's inflows and outflows and registers the "flow_step" with `sim` every
/// [flow] interval from the simulator's time. Call it before attach_gas: at a common time the
/// flow step then comes first, and the fluid step that follows gives the new particles their
/// drag at once. Returns nullptr when the scene has neither. `saved_state`: the /flow group of
/// a checkpoint, restored so that a resumed run continues bit for bit. Throws
/// std::invalid_argument for an inflow or outflow this system cannot run.
std::unique_ptr<FlowBoundaries> attach_flow(CollisionMethod& sim, const Scene& scene,
                                            const h5::Group* saved_state = nullptr);

/// The flow's series of one time-series row (S species, I inflows, O outflows; cumulative
/// since t = 0): particles_present (S), particle_seconds (S, the integral of particles_present
/// over time, s), entered and entered_mass (I; kg), waiting (I: particles owed but not yet
/// placed), left and left_mass (O; kg), flow_energy (J: Energies::flow).
void append_flow_series(const FlowBoundaries& flow, const CollisionMethod& sim, SeriesRow& row);

/// What the flow counters stood at when a stretch of the run began (for summary.json).
struct FlowStart {
  double last_step = 0;                  ///< Time of the flow's last step, s.
  std::vector<double> particle_seconds;  ///< Per species, s.
  std::vector<double> entered_mass;      ///< Per inflow, kg.
  std::vector<double> left_mass;         ///< Per outflow, kg.
  std::vector<std::uint64_t> entered;    ///< Per inflow.
  std::vector<std::uint64_t> left;       ///< Per outflow.
};
FlowStart flow_start(const FlowBoundaries& flow, double time);

/// The "flow" object of summary.json over the stretch [start_time, time]: each inflow's set and
/// measured mass flow (kg/s: the mass placed between the flow steps that began and ended the
/// stretch, over their distance) with the measurement's resolution (one particle's mass over
/// that time: placement is exact bookkeeping, not a random count), particles entered and
/// waiting, and when its slab was ever full, the blocked steps and what to do
/// (blocked_message); each outflow's mass flow and count over the stretch; the mean number of
/// particles present per species.
std::string flow_summary_json(const FlowBoundaries& flow, const FlowStart& start, double start_time,
                              double time);

}  // namespace carom
