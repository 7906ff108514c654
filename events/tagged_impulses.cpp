#include "events/tagged_impulses.hpp"

#include <stdexcept>
#include <string>
#include <unordered_map>

namespace carom {

void TaggedImpulses::tag(const std::vector<std::uint64_t>& tagged,
                         const std::vector<std::uint64_t>& method_ids, std::size_t species,
                         std::size_t walls) {
  const bool resumed = !ids.empty();
  if (resumed && (ids != tagged || species_count != species || wall_count != walls))
    throw std::invalid_argument("the tagged bodies of the saved state differ from the scene's");
  if (tagged.empty()) {
    slot_of.clear();
    return;
  }
  std::unordered_map<std::uint64_t, std::int32_t> slot_by_id;
  for (std::size_t k = 0; k < tagged.size(); ++k)
    if (!slot_by_id.emplace(tagged[k], static_cast<std::int32_t>(k)).second)
      throw std::invalid_argument("particle " + std::to_string(tagged[k]) + " is tagged twice");
  slot_of.assign(method_ids.size(), -1);
  std::size_t found = 0;
  for (std::size_t i = 0; i < method_ids.size(); ++i) {
    const auto it = slot_by_id.find(method_ids[i]);
    if (it == slot_by_id.end()) continue;
    slot_of[i] = it->second;
    ++found;
  }
  // A resumed run's body may have left (an outflow): its books stay, with no particle.
  if (found != tagged.size() && !resumed)
    throw std::invalid_argument("a tagged body's particle id is not among the particles");
  if (!resumed) {
    ids = tagged;
    species_count = species;
    wall_count = walls;
    impulse.assign(tagged.size() * partners(), Vec3::Zero());
    step_force.assign(tagged.size() * partners(), Vec3::Zero());
  }
}

}  // namespace carom
