#pragma once
/// Inflow and outflow (DESIGN.md section 3: insertion and removal events), the same for every
/// collision method: at each flow step (a synchronising action, so every particle's state is as
/// of the step's time) the particles beyond an outlet plane leave, and the particles each inflow
/// owes by its mass flow rate since the last step enter, placed at random without overlap in a
/// slab behind the inlet rectangle. The method applies the change (events/method.hpp,
/// ParticleChange).
///
/// API SKETCH — to be implemented in flow_boundaries.cpp (the helper may refine names and add
/// members, keeping the roles).
#include <cstdint>
#include <string>
#include <vector>

#include "core/hdf5.hpp"
#include "core/rng.hpp"
#include "core/system.hpp"
#include "events/method.hpp"

namespace carom {

/// One inflow ([[inflow]] of a scene): particles of one species enter through a rectangle on a
/// plane normal to a coordinate axis, at a given mass flow rate.
struct Inflow {
  std::string name;               ///< For outputs and messages.
  std::uint32_t species = 0;      ///< Index into System::species.
  int axis = 2;                   ///< Normal of the inlet plane: 0 x, 1 y, 2 z.
  double plane = 0;               ///< Position of the plane on `axis`, m.
  int direction = -1;             ///< Side the slab lies on, the way particles enter: +1 or -1.
  Vec3 lower = Vec3::Zero();      ///< Rectangle's lower corner, m (the `axis` component is ignored).
  Vec3 upper = Vec3::Zero();      ///< Rectangle's upper corner, m.
  double mass_flow = 0;           ///< kg/s.
  Vec3 velocity = Vec3::Zero();   ///< Mean velocity of entering particles, m/s.
  Vec3 velocity_spread = Vec3::Zero();  ///< Standard deviation of each component, m/s (Gaussian).
  double depth = 0;               ///< Slab thickness from the plane into the domain, m.
  int attempts = 100;             ///< Random tries per particle before it waits for the next step.
};

/// One outlet ([[outflow]]): particles whose centre is beyond the plane leave.
struct Outflow {
  std::string name;
  int axis = 2;        ///< 0 x, 1 y, 2 z.
  double plane = 0;    ///< m.
  int direction = -1;  ///< +1: centres above the plane leave; -1: below.
};

class FlowBoundaries {
 public:
  /// `system`: domain, walls, species (particles: those present at start_time, for ids).
  FlowBoundaries(std::vector<Inflow> inflows, std::vector<Outflow> outflows, const System& system,
                 std::uint64_t seed, double start_time);
  /// The flow step at `time`: every particle's state is as of `time`; fills `change`.
  void step(double time, const ParticleStore& particles, ParticleChange& change);
  /// Counters (cumulative since the start): per inflow entered count and mass (kg), particles
  /// still owed; per outflow left count and mass; per species particle-seconds present.
  // ... accessors
  void save(const h5::Group& group) const;
  void restore(const h5::Group& group);
};

}  // namespace carom
