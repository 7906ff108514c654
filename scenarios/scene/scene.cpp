#include "scenarios/scene/scene.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "scenarios/scene/gas_scene.hpp"
#include "scenarios/scene/analysis_scene.hpp"
#include "scenarios/scene/method_scene.hpp"
#include "scenarios/scene/overrides.hpp"
#include "scenarios/scene/walls_scene.hpp"

namespace carom {

std::uint32_t species_index(TableReader& t, std::string_view key, const Scene& scene) {
  const std::string name = t.required_string(key);
  std::vector<std::string> names;
  for (std::size_t s = 0; s < scene.system.species.size(); ++s) {
    if (scene.system.species[s].name == name) return static_cast<std::uint32_t>(s);
    names.push_back(scene.system.species[s].name);
  }
  const std::string guess = closest(name, names);
  t.fail(key, "names no species" + (guess.empty() ? std::string() : "; did you mean \"" + guess + "\"?"));
}

std::size_t region_index(TableReader& t, std::string_view key, const Scene& scene) {
  const std::string region = t.string(key, "domain");
  auto found = std::find_if(scene.regions.begin(), scene.regions.end(), [&](const Region& r) { return r.name == region; });
  if (found == scene.regions.end()) {
    std::vector<std::string> names;
    for (const Region& r : scene.regions) names.push_back(r.name);
    const std::string guess = closest(region, names);
    t.fail(key, "names no region (define it as [regions." + region + "] with min and max" +
                    (guess.empty() ? std::string(")") : "; did you mean \"" + guess + "\"?)"));
  }
  return static_cast<std::size_t>(found - scene.regions.begin());
}

namespace {

const std::vector<std::string> kSections = {"meta",       "domain", "species", "regions", "walls",  "particles",
                                            "collisions", "flight", "initial", "time",    "output", "engine", "gas",
                                            "analysis", "method"};
/// Sections of the design that later versions implement: named, so the error says so.
const std::vector<std::string> kLaterSections = {};

std::string vec_text(const Vec3& v) {
  std::string text("[");
  for (int k = 0; k < 3; ++k) {
    text += format_number(v[k]);
    text += k < 2 ? ", " : "]";
  }
  return text;
}

int axis_index(const std::string& name) { return name == "x" ? 0 : name == "y" ? 1 : 2; }

void read_meta(TableReader& root, Scene& scene, const std::string& fallback_name) {
  scene.name = fallback_name;
  if (auto meta = root.table("meta")) {
    scene.name = meta->string("name", fallback_name);
    scene.description = meta->string("description", "");
    meta->finish();
  }
}

void read_domain(TableReader& root, Scene& scene) {
  auto domain = root.table("domain");
  if (!domain) root.fail_table("the [domain] section is missing (keys min, max, periodic, gravity)");
  Domain& d = scene.system.domain;
  d.lower = domain->required_vector3("min", Range::any("lower corner of the box, m"));
  d.upper = domain->required_vector3("max", Range::any("upper corner of the box, m"));
  for (int k = 0; k < 3; ++k)
    if (!(d.upper[k] > d.lower[k]))
      domain->fail("max", "must exceed domain.min = " + vec_text(d.lower) + " on every axis (not on " +
                              std::string(1, "xyz"[k]) + ")");
  d.periodic = {false, false, false};
  for (const std::string& axis : domain->strings("periodic")) {
    if (axis != "x" && axis != "y" && axis != "z")
      domain->fail("periodic", "names an axis \"" + axis + "\"; allowed: any of \"x\", \"y\", \"z\"");
    if (d.periodic[axis_index(axis)]) domain->fail("periodic", "names axis \"" + axis + "\" twice");
    d.periodic[axis_index(axis)] = true;
  }
  scene.system.flight.gravity = domain->vector3("gravity", Vec3::Zero(), Range::any("gravitational acceleration, m/s^2"));
  domain->finish();
}

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
    scene.system.species.push_back(species);
  }
}

void read_regions(TableReader& root, Scene& scene) {
  const Domain& d = scene.system.domain;
  scene.regions.push_back(Region{"domain", d.lower, d.upper});
  auto regions = root.table("regions");
  if (!regions) return;
  for (const std::string& name : regions->keys()) {
    if (name == "domain") regions->fail(name, "is reserved for the whole domain; choose another region name");
    auto r = regions->table(name);
    Region region{name, r->required_vector3("min", Range::any("lower corner of the region, m")),
                  r->required_vector3("max", Range::any("upper corner of the region, m"))};
    for (int k = 0; k < 3; ++k) {
      if (!(region.upper[k] > region.lower[k]))
        r->fail("max", "must exceed " + r->key_path("min") + " = " + vec_text(region.lower) + " on every axis");
      if (region.lower[k] < d.lower[k] || region.upper[k] > d.upper[k])
        r->fail(region.lower[k] < d.lower[k] ? "min" : "max",
                "puts the region outside the domain [" + vec_text(d.lower) + ", " + vec_text(d.upper) + "] on axis " +
                    std::string(1, "xyz"[k]));
    }
    r->finish();
    scene.regions.push_back(region);
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

void read_listed(TableReader& root, Scene& scene) {
  for (TableReader p : root.tables("particles")) {
    ListedParticle particle;
    particle.where = p.where();
    particle.species = species_index(p, "species", scene);
    particle.position = p.required_vector3("position", Range::any("centre, m"));
    particle.velocity = p.vector3("velocity", Vec3::Zero(), Range::any("velocity, m/s"));
    particle.spin = p.vector3("spin", Vec3::Zero(), Range::any("angular velocity, rad/s"));
    p.finish();
    scene.listed.push_back(particle);
  }
}

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
    t->finish();
  }
  c->finish();
}

void read_initial(TableReader& root, Scene& scene) {
  if (auto i = root.table("initial")) {
    scene.seed = static_cast<std::uint64_t>(i->integer("seed", 1, 0, std::numeric_limits<std::int64_t>::max(), "random seed"));
    scene.temperature = i->number("temperature", 0.0, Range::non_negative("granular temperature T = m <v_x^2> of filled particles, J"));
    scene.rms_velocity = i->number("rms_velocity", 0.0, Range::non_negative("rms velocity of filled particles, m/s"));
    if (i->has("temperature") && i->has("rms_velocity"))
      i->fail("rms_velocity", "cannot be given together with initial.temperature; choose one");
    scene.settle_time = i->number("settle_time", 0.0, Range::non_negative("settling run before t = 0, s (0: none)"));
    scene.settle_where = i->where_key("settle_time");
    scene.settle_zero_velocity = i->boolean("settle_zero_velocity", false);
    if (i->has("settle_zero_velocity") && scene.settle_time == 0.0)
      i->fail("settle_zero_velocity", "is only used with initial.settle_time > 0");
    if (auto f = i->table("from_file")) {
      InitialFile file;
      file.where = f->where_key("path");
      file.written = f->required_string("path");
      if (file.written.empty()) f->fail("path", "must not be empty (a carom run.h5 or checkpoint.h5)");
      std::filesystem::path path(file.written);
      if (path.is_relative()) path = std::filesystem::path(scene.file).parent_path() / path;
      file.path = path.string();
      file.snapshot_given = f->has("snapshot");
      file.snapshot = f->integer("snapshot", -1, std::numeric_limits<std::int64_t>::min() + 1,
                                 std::numeric_limits<std::int64_t>::max(),
                                 "snapshot index in a run file: 0 first, -1 last, -2 the one before");
      f->finish();
      scene.from_file = file;
    }
    i->finish();
  }
}

void read_time_and_output(TableReader& root, Scene& scene) {
  auto t = root.table("time");
  if (!t) root.fail_table("the [time] section is missing (key end, s)");
  scene.end_time = t->number("end", Range::positive("simulated end time, s"));
  t->finish();
  OutputSchedule& out = scene.output;
  out.snapshot_every = scene.end_time / 100.0;
  out.sample_every = 0.0;
  if (auto o = root.table("output")) {
    out.snapshot_every = o->number("snapshot_every", out.snapshot_every, Range::non_negative("time between snapshots, s (0: only first and last)"));
    out.sample_every = o->number("sample_every", out.sample_every, Range::non_negative("time between time-series rows, s"));
    out.checkpoint_every = o->number("checkpoint_every", 0.0, Range::non_negative("time between checkpoints, s (0: only at the end or on interruption)"));
    o->finish();
  }
  if (out.sample_every == 0.0) out.sample_every = out.snapshot_every > 0 ? out.snapshot_every / 10.0 : scene.end_time / 1000.0;
}

void read_engine(TableReader& root, Scene& scene) {
  if (auto e = root.table("engine")) {
    scene.method.event_driven.grid_level_ratio = e->number("grid_level_ratio", scene.method.event_driven.grid_level_ratio,
                                               Range{0.0, 1.0, false, true, "size ratio that starts a new grid level (0: one grid)"});
    scene.method.event_driven.check_invariants = e->boolean("check_invariants", scene.method.event_driven.check_invariants);
    e->finish();
  }
}

void check_sections(const toml::table& table, const std::string& file) {
  TableReader probe(table, file, "");
  for (auto&& [key, value] : table) {
    const std::string name(key.str());
    if (std::find(kLaterSections.begin(), kLaterSections.end(), name) != kLaterSections.end())
      throw SceneError(probe.where(value) + ": [" + name + "] is not yet supported by this version of carom" +
                       " (remove it)");
  }
}

}  // namespace

Scene parse_scene(const std::string& text, const std::string& file, const std::vector<std::string>& overrides,
                  std::optional<std::uint64_t> seed) {
  toml::table table;
  try {
    table = toml::parse(std::string_view(text), std::string_view(file));
  } catch (const toml::parse_error& e) {
    throw SceneError(file + ":" + std::to_string(e.source().begin.line) + ":" +
                     std::to_string(e.source().begin.column) + ": not valid TOML: " + std::string(e.description()));
  }
  for (const std::string& assignment : overrides) apply_override(table, assignment);
  if (seed) apply_override(table, "initial.seed=" + std::to_string(*seed));

  Scene scene;
  scene.file = file;
  if (overrides.empty() && !seed) {
    scene.text = text;
  } else {
    std::ostringstream out;
    out << "# " << file << " with";
    for (const auto& a : overrides) out << " --set " << a;
    if (seed) out << " --seed " << *seed;
    out << "\n" << table << "\n";
    scene.text = out.str();
  }
  check_sections(table, file);
  TableReader root(table, file, "");
  for (const auto& s : kSections) root.allow({s});
  const std::string stem = std::filesystem::path(file).stem().string();
  read_meta(root, scene, stem);
  read_domain(root, scene);
  std::vector<TableReader> species_tables;
  read_species(root, scene, species_tables);
  read_regions(root, scene);
  read_fills(scene, species_tables);
  read_walls(root, scene);
  read_listed(root, scene);
  read_collisions(root, scene);
  read_flight_and_gas(root, scene);
  read_initial(root, scene);
  read_time_and_output(root, scene);
  read_engine(root, scene);
  read_analysis(root, scene);
  read_method(root, scene);
  root.finish();
  return scene;
}

Scene load_scene(const std::string& path, const std::vector<std::string>& overrides, std::optional<std::uint64_t> seed) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(path + ": cannot open the scene file");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_scene(text.str(), path, overrides, seed);
}

}  // namespace carom
