#pragma once
/// The inflows and outflows of a run (scene keys [[inflow]], [[outflow]]; SCENES.md): what each
/// is, the slab where an inflow's particles are placed, and the checks that a definition can be
/// simulated in a given system. FlowBoundaries (flow_boundaries.hpp) runs them.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/system.hpp"

namespace carom {

/// One inflow ([[inflow]] of a scene): particles of one species enter through a rectangle on a
/// plane normal to a coordinate axis, at a given mass flow rate. They are placed at random in a
/// slab of thickness `depth` on the `direction` side of the plane, behind the rectangle.
struct Inflow {
  std::string name;              ///< For outputs and messages.
  std::uint32_t species = 0;     ///< Index into System::species.
  int axis = 2;                  ///< Normal of the inlet plane: 0 x, 1 y, 2 z.
  double plane = 0;              ///< Position of the plane on `axis`, m.
  int direction = -1;            ///< Side of the plane the slab lies on: +1 above, -1 below.
  Vec3 lower = Vec3::Zero();     ///< Rectangle's lower corner, m (the `axis` component is ignored).
  Vec3 upper = Vec3::Zero();     ///< Rectangle's upper corner, m (the `axis` component is ignored).
  double mass_flow = 0;          ///< Mass flow rate, kg/s.
  Vec3 velocity = Vec3::Zero();  ///< Mean velocity of entering particles, m/s.
  Vec3 velocity_spread = Vec3::Zero();  ///< Standard deviation of each component, m/s (Gaussian).
  double depth = 0;    ///< Slab thickness from the plane, m; 0: inflow_depth's default.
  int attempts = 100;  ///< Random tries per particle before it waits for the next flow step.
};

/// One outlet ([[outflow]]): particles whose centre is beyond the plane leave.
struct Outflow {
  std::string name;    ///< For outputs and messages.
  int axis = 2;        ///< Normal of the outlet plane: 0 x, 1 y, 2 z.
  double plane = 0;    ///< Position of the plane on `axis`, m.
  int direction = -1;  ///< +1: centres above the plane leave; -1: centres below it leave.
};

/// An axis-aligned box, m.
struct Box {
  Vec3 lower = Vec3::Zero();  ///< m.
  Vec3 upper = Vec3::Zero();  ///< m.
  /// True when r lies in the closed box.
  bool contains(const Vec3& r) const {
    return (r.array() >= lower.array()).all() && (r.array() <= upper.array()).all();
  }
};

/// What is wrong with a flow definition: the scene key at fault ("plane", "depth", ...) and the
/// problem in words (with the numbers and the allowed range).
struct FlowProblem {
  std::string key;
  std::string problem;
};

/// The slab thickness of an inflow, m: its depth when set, else
/// max(2 d, |v_n| interval + d) with d the species' diameter and v_n the mean velocity along the
/// axis: particles moving at the mean speed clear the slab's depth between two flow steps
/// `interval` (s) apart, and the slab holds at least two layers.
double inflow_depth(const Inflow& inflow, const Species& species, double interval);

/// The slab of an inflow (depth resolved), m: the rectangle times [plane, plane + direction depth].
Box inflow_slab(const Inflow& inflow, double depth);

/// Where an entering particle's centre may go, m: the slab shrunk by the particle's radius on
/// every side, so that the sphere lies inside the slab. Empty (upper < lower on some axis) when
/// the slab is thinner than one diameter.
Box inflow_centres(const Inflow& inflow, double depth, double radius);

/// The first problem of an inflow in this system with flow steps `interval` (s) apart, or
/// nullopt: an unknown or fixed species, a periodic axis, a plane not strictly inside the
/// domain, a direction other than +-1, mass_flow <= 0, an empty rectangle or one outside the
/// domain, a negative spread, attempts < 1, a slab reaching outside the domain or too thin for
/// one particle.
std::optional<FlowProblem> check_inflow(const Inflow& inflow, const System& system,
                                        double interval);
/// The first problem of an outflow in this domain, or nullopt: a periodic axis, a plane not
/// strictly inside the domain, a direction other than +-1.
std::optional<FlowProblem> check_outflow(const Outflow& outflow, const Domain& domain);
/// A problem when part of the inflow's slab lies beyond the outlet (its particles would leave
/// at the next flow step), else nullopt (key "plane" of the inflow).
std::optional<FlowProblem> check_inflow_against_outflow(const Inflow& inflow, double depth,
                                                        const Outflow& outflow);

/// True when a centre at r (m) is beyond the outlet plane (strictly).
inline bool beyond(const Outflow& outflow, const Vec3& r) {
  return outflow.direction * (r[outflow.axis] - outflow.plane) > 0.0;
}

/// "x", "y" or "z".
inline const char* axis_name(int axis) {
  return axis == 0 ? "x" : axis == 1 ? "y" : "z";
}

}  // namespace carom
