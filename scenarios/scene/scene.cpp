#include "scenarios/scene/scene.hpp"
#include "scenarios/scene/input_file.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "scenarios/scene/analysis_scene.hpp"
#include "scenarios/scene/collisions_scene.hpp"
#include "scenarios/scene/domain_scene.hpp"
#include "scenarios/scene/flow_scene.hpp"
#include "scenarios/scene/gas_scene.hpp"
#include "scenarios/scene/initial_scene.hpp"
#include "scenarios/scene/method_scene.hpp"
#include "scenarios/scene/monte_carlo_scene.hpp"
#include "scenarios/scene/overrides.hpp"
#include "scenarios/scene/particles_scene.hpp"
#include "scenarios/scene/soft_sphere_scene.hpp"
#include "scenarios/scene/species_scene.hpp"
#include "scenarios/scene/time_scene.hpp"
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

const std::vector<std::string> kSections = {
    "meta",   "domain",      "species",     "regions", "walls",   "particles", "collisions",
    "flight", "initial",     "time",        "output",  "engine",  "gas",       "analysis",
    "method", "soft_sphere", "monte_carlo", "inflow",  "outflow", "flow"};

/// Largest scene file, bytes: a scene is a page of keys (particles listed one by one included).
constexpr std::size_t kMaxSceneBytes = 64u << 20;

/// Longest meta.name, bytes.
constexpr std::size_t kMaxSceneName = 1024;

void read_meta(TableReader& root, Scene& scene, const std::string& fallback_name) {
  scene.name = fallback_name;
  if (auto meta = root.table("meta")) {
    scene.name = meta->string("name", fallback_name);
    // The name is an HDF5 attribute of every output (HDF5 keeps attributes under 64 kB) and
    // heads reports: a short label, not a document.
    if (scene.name.size() > kMaxSceneName)
      meta->fail("name", "is " + std::to_string(scene.name.size()) + " bytes long; a name has at most " +
                             std::to_string(kMaxSceneName) + " (put longer text in meta.description)");
    scene.description = meta->string("description", "");
    meta->finish();
  }
}

}  // namespace

Scene parse_scene(const std::string& text, const std::string& file, const std::vector<std::string>& overrides,
                  std::optional<std::uint64_t> seed, const std::vector<std::string>& override_origins) {
  toml::table table;
  try {
    table = toml::parse(std::string_view(text), std::string_view(file));
  } catch (const toml::parse_error& e) {
    throw SceneError(file + ":" + std::to_string(e.source().begin.line) + ":" +
                     std::to_string(e.source().begin.column) + ": not valid TOML: " + std::string(e.description()));
  }
  // A sweep file given where a scene belongs (carom check/run fines_sweep.toml): say what to run.
  if (const toml::node* sweep = table.get("sweep"); sweep != nullptr && sweep->is_table())
    throw SceneError(file + ":" + std::to_string(sweep->source().begin.line) +
                     ": this is a sweep file ([sweep]), not a scene: run it with `carom sweep " + file +
                     "`, or check every case with `carom sweep " + file + " --dry-run`");
  for (std::size_t k = 0; k < overrides.size(); ++k)
    apply_override(table, overrides[k], k < override_origins.size() ? override_origins[k] : std::string());
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
  read_soft_sphere(root, scene);
  read_monte_carlo(root, scene);
  read_flow(root, scene);
  root.finish();
  return scene;
}

Scene load_scene(const std::string& path, const std::vector<std::string>& overrides, std::optional<std::uint64_t> seed,
                 const std::vector<std::string>& override_origins) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error))
    throw SceneError(path + ": is a directory, not a scene file (give the .toml file itself, e.g. " +
                     (std::filesystem::path(path) / "scene.toml").string() + ")");
  std::string text;
  try {
    text = without_bom(read_regular_file(path, "the scene file", kMaxSceneBytes));
  } catch (const SceneError& e) {
    if (!std::filesystem::exists(path, error)) throw SceneError(path + ": cannot open the scene file");
    throw;
  }
  return parse_scene(text, path, overrides, seed, override_origins);
}

}  // namespace carom
