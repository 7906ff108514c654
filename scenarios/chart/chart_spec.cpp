#include "scenarios/chart/chart_spec.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace carom {

namespace fs = std::filesystem;

namespace {

/// True for a dotted path: non-empty parts, no '=' (what --set and summary.json keys look like).
bool dotted_key(const std::string& key) {
  return !key.empty() && key.front() != '.' && key.back() != '.' &&
         key.find("..") == std::string::npos && key.find('=') == std::string::npos &&
         key.find_first_of(" \t\n") == std::string::npos;
}

/// The changes of a `set` key (absent: none) of a table read by `reader`.
void read_set(TableReader& reader, const toml::table& raw, std::vector<std::string>& out,
              std::vector<std::string>& origins) {
  if (!reader.has("set")) return;
  const auto* set = raw.get("set")->as_table();
  if (set == nullptr)
    reader.fail("set",
                "is not a table (allowed: scene changes as for --set, e.g. set = { "
                "\"method.kind\" = \"soft_sphere\", \"soft_sphere.time_step\" = 1e-4 })");
  flatten_scene_changes(*set, reader, reader.key_path("set"), out, origins);
}

std::string key_of(const std::string& assignment) {
  return assignment.substr(0, assignment.find('='));
}

ChartObservable read_observable(TableReader& reader) {
  reader.allow({"key", "tolerance", "error"});
  reader.finish();
  ChartObservable o;
  o.key = reader.required_string("key");
  o.where = reader.where_key("key");
  if (!dotted_key(o.key))
    reader.fail("key",
                "is not a dotted path of a number in summary.json (allowed: e.g. "
                "\"analysis.collision_frequency.sphere-sphere\", \"pressure.total\"; "
                "`carom sweep`'s summary.csv lists them all)");
  if (!reader.has("tolerance"))
    reader.fail("tolerance",
                "is missing (allowed: a number > 0, the largest error a user accepts, in the "
                "measure of `error`)");
  o.tolerance = reader.number("tolerance", Range::positive("the largest acceptable error"));
  const std::string measure = reader.string("error", "relative", {"relative", "absolute"});
  o.measure = measure == "relative" ? ErrorMeasure::Relative : ErrorMeasure::Absolute;
  return o;
}

ChartVariant read_variant(TableReader& reader, const toml::table& raw) {
  reader.allow({"name", "set"});
  reader.finish();
  ChartVariant v;
  v.name = reader.required_string("name");
  v.where = reader.where_key("name");
  if (v.name.empty() || v.name.find_first_of("\n\r\t|") != std::string::npos)
    reader.fail("name",
                "is not a variant name (allowed: a non-empty label without '|', tabs or line "
                "breaks, e.g. \"soft dt=1e-3\")");
  read_set(reader, raw, v.sets, v.origins);
  return v;
}

}  // namespace

ChartSpec read_chart(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(path + ": cannot open the chart file");
  std::ostringstream text;
  text << in.rdbuf();
  toml::table root;
  try {
    const std::string document = text.str();
    root = toml::parse(std::string_view(document), std::string_view(path));
  } catch (const toml::parse_error& e) {
    throw SceneError(path + ":" + std::to_string(e.source().begin.line) + ":" +
                     std::to_string(e.source().begin.column) +
                     ": not valid TOML: " + std::string(e.description()));
  }
  const toml::table* raw = root.get_as<toml::table>("chart");
  if (raw == nullptr) {
    if (const toml::table* sweep = root.get_as<toml::table>("sweep"))
      throw SceneError(path + ":" + std::to_string(sweep->source().begin.line) +
                       ": this is a sweep file ([sweep]), not a chart: run it with `carom sweep " +
                       path + "`");
    throw SceneError(path +
                     ": no [chart] table; a chart file starts with [chart] and scene = "
                     "\"SCENE.toml\" (see scenarios/chart/CHARTS.md)" +
                     (root.contains("domain")
                          ? "; this looks like a scene: run it with `carom run " + path + "`"
                          : std::string()));
  }
  TableReader top(root, path, "");
  std::optional<TableReader> chart = top.table("chart");
  top.finish();
  chart->allow({"scene", "out", "seeds", "reference", "set", "observable", "variant"});
  chart->finish();  // a misspelt key first: what it stood for is then no surprise

  ChartSpec spec;
  spec.file = path;
  const std::string scene = chart->required_string("scene");
  const fs::path folder = fs::path(path).parent_path();
  spec.scene = fs::path(scene).is_absolute() || folder.empty() ? scene : (folder / scene).string();
  if (!fs::exists(spec.scene) || fs::is_directory(spec.scene))
    chart->fail("scene", "names no scene file (looked for " + spec.scene + ")");
  spec.out = chart->string("out", fs::path(path).stem().string() + ".out");
  if (spec.out.empty()) chart->fail("out", "is empty (allowed: a directory path)");
  {
    const std::string allowed =
        "(allowed: an array of at least two distinct integers >= 0, e.g. seeds = [1, 2, 3]; the "
        "standard errors need two seeds)";
    if (!chart->has("seeds")) chart->fail("seeds", "is missing " + allowed);
    spec.seeds = read_seeds(*chart, *raw, 2, allowed);
  }
  read_set(*chart, *raw, spec.fixed, spec.fixed_origins);

  std::vector<TableReader> observables = chart->tables("observable");
  if (observables.empty())
    chart->fail_table(
        "no [[chart.observable]]; give at least one, e.g. [[chart.observable]] key = "
        "\"analysis.collision_frequency.sphere-sphere\", tolerance = 0.02");
  for (TableReader& reader : observables) {
    ChartObservable o = read_observable(reader);
    for (const ChartObservable& other : spec.observables)
      if (other.key == o.key)
        reader.fail("key", "is compared twice (also at " + other.where + "; allowed: each once)");
    spec.observables.push_back(std::move(o));
  }

  std::vector<TableReader> variants = chart->tables("variant");
  const toml::array* variants_raw = raw->get_as<toml::array>("variant");
  for (std::size_t k = 0; k < variants.size(); ++k) {
    ChartVariant v = read_variant(variants[k], *variants_raw->get(k)->as_table());
    for (const ChartVariant& other : spec.variants) {
      if (other.name == v.name)
        variants[k].fail("name", "is taken (also at " + other.where + "; allowed: unique names)");
      if (other.sets == v.sets)
        variants[k].fail("set", "makes the same changes as variant \"" + other.name + "\" (at " +
                                    other.where + "; allowed: variants that differ)");
    }
    for (const std::string& assignment : v.sets)
      for (const std::string& fixed : spec.fixed)
        if (key_of(fixed) == key_of(assignment))
          variants[k].fail("set", "changes \"" + key_of(assignment) +
                                      "\", which chart.set already fixes for every variant "
                                      "(allowed: a key either in chart.set or in the variants)");
    spec.variants.push_back(std::move(v));
  }
  if (spec.variants.size() < 2)
    chart->fail_table("has " + std::to_string(spec.variants.size()) +
                      " [[chart.variant]]; give at least two: the reference and one to compare "
                      "with it");

  std::string names;
  for (const ChartVariant& v : spec.variants)
    names += (names.empty() ? "\"" : ", \"") + v.name + "\"";
  const std::string reference = chart->required_string("reference");
  const auto found = std::find_if(spec.variants.begin(), spec.variants.end(),
                                  [&](const ChartVariant& v) { return v.name == reference; });
  if (found == spec.variants.end())
    chart->fail("reference", "names no variant (allowed: " + names + ")");
  spec.reference = static_cast<std::size_t>(found - spec.variants.begin());
  return spec;
}

SweepSpec chart_sweep(const ChartSpec& chart) {
  SweepSpec sweep;
  sweep.file = chart.file;
  sweep.scene = chart.scene;
  sweep.out = chart.out;
  sweep.fixed = chart.fixed;
  sweep.fixed_origins = chart.fixed_origins;
  sweep.seeds = chart.seeds;
  SweepAxis axis;
  axis.key = "variant";
  axis.label_only = true;
  for (const ChartVariant& v : chart.variants) {
    SweepValue value;
    value.text = v.name;
    value.label = v.name;
    value.where = v.where;
    value.sets = v.sets;
    value.set_origins = v.origins;
    axis.values.push_back(std::move(value));
  }
  sweep.axes.push_back(std::move(axis));
  return sweep;
}

}  // namespace carom
