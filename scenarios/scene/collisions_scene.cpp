#include "scenarios/scene/collisions_scene.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace carom {

namespace {

/// A contact law: keys e, mu, beta0, mu_static; missing ones come from `base`.
ContactLaw read_law(TableReader& t, const ContactLaw& base) {
  ContactLaw law = base;
  law.restitution = t.number("e", base.restitution, Range::closed(0.0, 1.0, "normal restitution"));
  law.friction = t.number("mu", base.friction, Range::non_negative("Coulomb friction coefficient"));
  law.tangential_restitution = t.number("beta0", base.tangential_restitution,
                                        Range::closed(-1.0, 1.0, "tangential restitution, -1 smooth, +1 perfectly rough"));
  if (t.has("mu_static")) {
    law.static_friction = t.number("mu_static", Range{law.friction, std::numeric_limits<double>::infinity(), false, true,
                                                      "static friction coefficient, at least mu"});
  }
  try {
    law.validate(t.where() + ": " + (t.path().empty() ? "collisions" : t.path()));
  } catch (const std::invalid_argument& e) {
    throw SceneError(e.what());
  }
  return law;
}

}  // namespace

void read_collisions(TableReader& root, Scene& scene) {
  System& system = scene.system;
  ContactLaw pair_default, wall_default;
  auto collisions = root.table("collisions");
  std::optional<TableReader> c = collisions;
  if (c) {
    if (auto t = c->table("default")) {
      pair_default = read_law(*t, ContactLaw{});
      t->finish();
    }
    wall_default = pair_default;
    if (auto t = c->table("walls")) {
      wall_default = read_law(*t, pair_default);
      t->finish();
    }
  }
  system.materials = MaterialTable(system.species.size(), system.walls.size(), pair_default, wall_default);
  if (!c) return;
  for (TableReader p : c->tables("pair")) {
    const auto names = p.strings("species");
    if (names.size() != 2) p.fail("species", "must name two species, e.g. [\"large\", \"fines\"]");
    std::uint32_t index[2];
    for (int k = 0; k < 2; ++k) {
      auto it = std::find_if(system.species.begin(), system.species.end(), [&](const Species& s) { return s.name == names[k]; });
      if (it == system.species.end()) p.fail("species", "names \"" + names[k] + "\", which is no species");
      index[k] = static_cast<std::uint32_t>(it - system.species.begin());
    }
    system.materials.set_pair(index[0], index[1], read_law(p, pair_default));
    p.finish();
  }
  for (TableReader w : c->tables("wall")) {
    std::optional<std::uint32_t> species;
    if (w.has("species")) species = species_index(w, "species", scene);
    std::optional<std::size_t> wall;
    if (w.has("wall")) {
      const std::string name = w.required_string("wall");
      std::vector<std::string> names;
      for (std::size_t k = 0; k < system.walls.size(); ++k) {
        if (system.walls[k].name == name) wall = k;
        names.push_back(system.walls[k].name);
      }
      if (!wall) {
        const std::string guess = closest(name, names);
        w.fail("wall", "names no wall (walls: box walls on non-periodic axes, x_low ... z_high, and [[walls]])" +
                           (guess.empty() ? std::string() : "; did you mean \"" + guess + "\"?"));
      }
    }
    const ContactLaw law = read_law(w, wall_default);
    for (std::size_t s = 0; s < system.species.size(); ++s)
      for (std::size_t k = 0; k < system.walls.size(); ++k)
        if ((!species || *species == s) && (!wall || *wall == k)) system.materials.set_wall(s, k, law);
    w.finish();
  }
  CollapseOptions& collapse = scene.method.event_driven.collapse;
  if (auto t = c->table("collapse")) {
    const std::string model = t->string("model", "none", {"none", "tc"});
    if (model == "tc") {
      collapse.contact_time = t->number("contact_time", Range::positive("TC model contact duration, s"));
    } else if (t->has("contact_time")) {
      t->fail("contact_time", "is only used with model = \"tc\"");
    }
    collapse.elastic_below_speed = t->number("elastic_below_speed", 0.0, Range::non_negative("impact speed below which collisions are elastic, m/s"));
    collapse.stall_collisions = static_cast<std::uint64_t>(
        t->integer("stall_collisions", 1000, 1, std::numeric_limits<std::int64_t>::max(), "collisions of one particle within stall_window that mean collapse"));
    collapse.stall_window = t->number("stall_window", 0.0, Range::non_negative("window of the stall detector, s (0: automatic)"));
    if (model == "tc")
      collapse.max_collisions_per_contact_time = t->number(
          "max_collisions_per_contact_time", collapse.max_collisions_per_contact_time,
          Range::non_negative("collisions per particle within one contact_time that mean lasting contacts (0: off)"));
    else if (t->has("max_collisions_per_contact_time"))
      t->fail("max_collisions_per_contact_time",
              "is only used with model = \"tc\" (its contact_time is the time scale); without it, set "
              "max_collision_frequency");
    if (auto limit = t->optional_number(
            "max_collision_frequency",
            Range::non_negative("collisions per particle per second that mean lasting contacts, 1/s (0: off)")))
      collapse.max_collision_frequency = *limit;
    t->finish();
  }
  c->finish();
}

}  // namespace carom
