#pragma once
/// The plain event record: what will happen to a particle, when, and with whom.
#include <cstdint>

#include "core/vec3.hpp"

namespace carom {

enum class EventKind : std::uint8_t {
  None,          ///< Nothing predicted (time = kNever).
  Pair,          ///< Collision with particle `partner`.
  Wall,          ///< Collision with wall number `partner`.
  CellCrossing,  ///< Leaving the neighbour-grid cell through face `partner` = 2 axis + (dir > 0).
};

/// One particle's earliest predicted event. An event with a particle partner stays valid only
/// while that partner's event counter still equals `partner_counter` (lazy invalidation).
struct Event {
  double time = kNever;                ///< When it happens, s.
  std::int32_t partner = -1;           ///< Particle index, wall index or face code (see kind).
  std::uint32_t partner_counter = 0;   ///< Partner's event counter when this was predicted.
  EventKind kind = EventKind::None;
};

}  // namespace carom
