#include "events/method_factory.hpp"

#include "events/event_driven/engine.hpp"
#include "events/soft_sphere/engine.hpp"
#include "events/monte_carlo/engine.hpp"

#include <stdexcept>
#include <string>

namespace carom {

std::unique_ptr<CollisionMethod> make_method(System system, const MethodSettings& settings) {
  switch (settings.kind) {
    case MethodKind::EventDriven:
      return std::make_unique<EventDrivenEngine>(std::move(system), settings.event_driven);
    case MethodKind::SoftSphere:
      return std::make_unique<SoftSphereEngine>(std::move(system), settings.soft_sphere);
    case MethodKind::MonteCarlo:
      return std::make_unique<MonteCarloEngine>(std::move(system), settings.monte_carlo);
  }
  throw std::logic_error("make_method: unknown method kind");
}

std::unique_ptr<CollisionMethod> restore_method(System system, const MethodSettings& settings,
                                                const h5::Group& saved) {
  // Checkpoints written before there were several methods have no attribute: event-driven.
  const std::string stored =
      saved.has_attribute("method") ? saved.attribute<std::string>("method") : "event_driven";
  if (stored != method_name(settings.kind))
    saved.fail("holds the state of method '" + stored + "', but the scene's method is '" +
               std::string(method_name(settings.kind)) + "'");
  switch (settings.kind) {
    case MethodKind::EventDriven:
      return std::make_unique<EventDrivenEngine>(std::move(system), settings.event_driven,
                                                 read_engine_state(saved));
    case MethodKind::SoftSphere:
      return std::make_unique<SoftSphereEngine>(std::move(system), settings.soft_sphere, saved);
    case MethodKind::MonteCarlo:
      return std::make_unique<MonteCarloEngine>(std::move(system), settings.monte_carlo,
                                                read_monte_carlo_state(saved));
  }
  throw std::logic_error("restore_method: unknown method kind");
}

}  // namespace carom
