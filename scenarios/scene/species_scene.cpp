#include "scenarios/scene/species_scene.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace carom {

void read_species(TableReader& root, Scene& scene, std::vector<TableReader>& species_tables) {
  species_tables = root.tables("species");
  if (species_tables.empty()) root.fail_table("no [[species]] given: at least one species is needed");
  for (TableReader& s : species_tables) {
    Species species;
    species.name = s.required_string("name");
    if (species.name.empty()) s.fail("name", "must not be empty");
    for (const Species& other : scene.system.species)
      if (other.name == species.name) s.fail("name", "is used by two species; names must be unique");
    species.diameter = s.number("diameter", Range::positive("sphere diameter, m"));
    species.density = s.number("density", Range::positive("solid density, kg/m^3"));
    species.fixed = s.boolean("fixed", false);
    // Elastic constants: used by the soft-sphere method's Hertz–Mindlin contacts, ignored by
    // the hard-sphere methods (so one scene runs with either).
    ElasticMaterial elastic;
    elastic.young_modulus = s.number("young_modulus", 0.0, Range::non_negative("Young's modulus E, Pa (soft spheres; 0: not given)"));
    elastic.poisson_ratio = s.number("poisson_ratio", 0.3, Range{0.0, 0.5, false, true, "Poisson ratio (soft spheres)"});
    scene.method.soft_sphere.species_materials.push_back(elastic);
    scene.system.species.push_back(species);
  }
}

void read_fills(Scene& scene, std::vector<TableReader>& species_tables) {
  scene.fills.assign(scene.system.species.size(), std::nullopt);
  for (std::size_t s = 0; s < species_tables.size(); ++s) {
    auto f = species_tables[s].table("fill");
    species_tables[s].finish();
    if (!f) continue;
    Fill fill;
    fill.where = f->where();
    fill.region = region_index(*f, "region", scene);
    int given = 0;
    if (f->has("count")) {
      fill.amount = Fill::Amount::Count;
      fill.value = static_cast<double>(f->integer("count", 0, 1, 100'000'000, "number of particles"));
      ++given;
    }
    if (f->has("volume_fraction")) {
      fill.amount = Fill::Amount::VolumeFraction;
      fill.value = f->number("volume_fraction", Range{0.0, 0.74, true, false, "solid volume / region volume (0.74: FCC close packing)"});
      ++given;
    }
    if (f->has("mass_fraction")) {
      fill.amount = Fill::Amount::MassFraction;
      fill.value = f->number("mass_fraction", Range{0.0, 1.0, false, true, "this species' mass / mass of all solids (0: none, e.g. the reference case of a sweep)"});
      ++given;
    }
    for (const char* key : {"count", "volume_fraction", "mass_fraction"})
      if (f->has(key)) {
        fill.amount_key = f->key_path(key);
        fill.amount_where = f->where_key(key);
        fill.amount_text = fill.amount == Fill::Amount::Count ? std::to_string(static_cast<std::int64_t>(fill.value))
                                                              : format_number(fill.value);
      }
    if (given != 1)
      f->fail_table("give exactly one of count, volume_fraction or mass_fraction (" + std::to_string(given) + " given)");
    const std::string arrangement = f->string("arrangement", "random", {"random", "fcc", "cubic"});
    fill.arrangement = arrangement == "fcc"     ? Fill::Arrangement::Fcc
                       : arrangement == "cubic" ? Fill::Arrangement::Cubic
                                                : Fill::Arrangement::Random;
    f->finish();
    scene.fills[s] = fill;
  }
}

}  // namespace carom
