#pragma once
/// Contact laws per species pair and per species-wall pair.
#include <cstddef>
#include <vector>

#include "contact_law.hpp"

namespace carom {

/// A symmetric table of pair laws (species x species) and a species x wall table.
class MaterialTable {
 public:
  MaterialTable() = default;
  /// Every pair and every wall starts with `pair_default` / `wall_default`.
  MaterialTable(std::size_t species_count, std::size_t wall_count, const ContactLaw& pair_default,
                const ContactLaw& wall_default)
      : species_(species_count),
        walls_(wall_count),
        pair_(species_count * species_count, pair_default),
        wall_(species_count * wall_count, wall_default) {}

  /// Law between species s and t (symmetric).
  const ContactLaw& pair(std::size_t s, std::size_t t) const { return pair_[s * species_ + t]; }
  /// Law between species s and wall w.
  const ContactLaw& wall(std::size_t s, std::size_t w) const { return wall_[s * walls_ + w]; }

  void set_pair(std::size_t s, std::size_t t, const ContactLaw& law) {
    pair_[s * species_ + t] = law;
    pair_[t * species_ + s] = law;
  }
  void set_wall(std::size_t s, std::size_t w, const ContactLaw& law) { wall_[s * walls_ + w] = law; }

  std::size_t species_count() const { return species_; }
  std::size_t wall_count() const { return walls_; }

 private:
  std::size_t species_ = 0;
  std::size_t walls_ = 0;
  std::vector<ContactLaw> pair_;
  std::vector<ContactLaw> wall_;
};

}  // namespace carom
