#include "scenarios/scene/monte_carlo_scene.hpp"

#include <limits>
#include <string>

namespace carom {

void read_monte_carlo(TableReader& root, Scene& scene) {
  MonteCarloOptions& mc = scene.method.monte_carlo;
  // Kick flights are ballistic between the kicks (the kicks are the gas coupling's).
  mc.flight_model = scene.flight.model == FlightModel::Relax ? FlightModel::Relax : FlightModel::Ballistic;
  // A stream of its own: the placement's seed, moved on so the two never share numbers.
  mc.seed = scene.seed ^ 0x9e3779b97f4a7c15ULL;
  auto m = root.table("monte_carlo");
  if (!m) return;
  mc.time_step = m->number("time_step", 0.0,
                           Range::non_negative("particle time step dt_p, s (0: 0.1 mean free time)"));
  mc.cell_size = m->number("cell_size", 0.0,
                           Range::non_negative("collision cell edge, m (0: 4 largest diameters, 32 particles a cell)"));
  const std::string frequency = m->string("frequency", "mean_relative_speed", {"mean_relative_speed", "mean_velocity"});
  mc.frequency = frequency == "mean_velocity" ? CollisionFrequency::MeanVelocity : CollisionFrequency::MeanRelativeSpeed;
  const std::string contact = m->string("contact_value", "none", {"none", "enskog"});
  mc.contact_value = contact == "enskog" ? ContactValue::Enskog : ContactValue::None;
  const std::string partner =
      m->string("partner", "gaussian", {"gaussian", "cell_particle", "cell_mean"});
  mc.partner = partner == "cell_particle" ? PartnerModel::CellParticle
               : partner == "cell_mean"   ? PartnerModel::CellMean
                                          : PartnerModel::Gaussian;
  if (m->has("seed"))
    mc.seed = static_cast<std::uint64_t>(
        m->integer("seed", 1, 0, std::numeric_limits<std::int64_t>::max(), "seed of the collision random numbers"));
  mc.max_collisions_per_step =
      m->number("max_collisions_per_step", mc.max_collisions_per_step,
                Range::positive("mean collisions per particle in one step above which the run stops"));
  m->finish();
}

}  // namespace carom
