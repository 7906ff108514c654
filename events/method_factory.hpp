#pragma once
/// Choosing a collision method (`[method] kind` of a scene) and building it, fresh or from a
/// checkpoint. A new method adds its kind here and its folder under events/.
#include <array>
#include <memory>
#include <string_view>

#include "core/hdf5.hpp"
#include "core/system.hpp"
#include "events/event_driven/options.hpp"
#include "events/soft_sphere/options.hpp"
#include "events/method.hpp"
#include "events/monte_carlo/options.hpp"

namespace carom {

/// The collision methods (core/DESIGN.md, "Methods").
enum class MethodKind {
  EventDriven,  ///< Exact flights and binary hard-sphere collisions (events/event_driven/).
  SoftSphere,   ///< Soft-sphere DEM: contact forces at a fixed step (events/soft_sphere/).
  MonteCarlo,   ///< Time steps, collisions with fictitious partners (events/monte_carlo/).
};

/// The scene names of the methods, in MethodKind order.
inline constexpr std::array<std::string_view, 3> kMethodNames{"event_driven", "soft_sphere",
                                                              "monte_carlo"};

/// What a scene says about its method: which one, and each method's own settings.
struct MethodSettings {
  MethodKind kind = MethodKind::EventDriven;
  EventDrivenOptions event_driven;  ///< Flights, collapse remedies, grid (event_driven).
  SoftSphereOptions soft_sphere;    ///< Contact model, elastic constants, step (soft_sphere).
  MonteCarloOptions monte_carlo;    ///< Step, cells, collision frequency, seed (monte_carlo).
};

/// The scene name of a method.
inline std::string_view method_name(MethodKind kind) { return kMethodNames[static_cast<int>(kind)]; }

/// Builds the method for `system` (its particles as of their clocks). Throws
/// std::invalid_argument when the system is not valid for it (overlaps, bad laws, ...).
std::unique_ptr<CollisionMethod> make_method(System system, const MethodSettings& settings);

/// Rebuilds a saved method (CollisionMethod::save_state wrote `saved`): `system` supplies box,
/// walls, species and laws. Throws std::runtime_error when `saved` holds another method's state
/// (naming both) or is incomplete.
std::unique_ptr<CollisionMethod> restore_method(System system, const MethodSettings& settings,
                                                const h5::Group& saved);

}  // namespace carom
