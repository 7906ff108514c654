#include "scenarios/sweep/sweep_spec.hpp"
#include "scenarios/scene/input_file.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "scenarios/scene/scene_reader.hpp"

namespace carom {

namespace fs = std::filesystem;

namespace {

/// A TOML basic string holding `text`.
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    out += c;
  }
  return out + "\"";
}

/// The value as TOML text for --set, or "" when it cannot be one (tables, dates).
std::string override_text(const toml::node& node) {
  if (const auto* f = node.as_floating_point()) {
    std::string text = format_number(f->get());
    // Keep it a float: "1" would read back as an integer.
    if (text.find_first_of(".eni") == std::string::npos) text += ".0";
    return text;
  }
  if (const auto* i = node.as_integer()) return std::to_string(i->get());
  if (const auto* b = node.as_boolean()) return b->get() ? "true" : "false";
  if (const auto* s = node.as_string()) return quoted(s->get());
  if (const auto* a = node.as_array()) {
    std::string text = "[";
    for (std::size_t k = 0; k < a->size(); ++k) {
      const std::string element = override_text(*a->get(k));
      if (element.empty()) return "";
      text += (k ? ", " : "") + element;
    }
    return text + "]";
  }
  return "";
}

std::optional<double> number_of(const toml::node& node) {
  if (const auto* f = node.as_floating_point()) return f->get();
  if (const auto* i = node.as_integer()) return static_cast<double>(i->get());
  return std::nullopt;
}

/// Flattens a table of scene changes into "key=value" (nested tables give dotted keys).
void flatten_set(const toml::table& table, const std::string& prefix, const TableReader& reader,
                 const std::string& name, std::vector<std::string>& out,
                 std::vector<std::string>& origins) {
  for (auto&& [key, value] : table) {
    const std::string path =
        prefix.empty() ? std::string(key.str()) : prefix + "." + std::string(key.str());
    if (const auto* t = value.as_table()) {
      flatten_set(*t, path, reader, name, out, origins);
      continue;
    }
    const std::string text = override_text(value);
    if (text.empty())
      throw SceneError(
          reader.where(value) + ": " + name + ": \"" + path + "\" = " + value_text(value) +
          " is not a value --set can take (allowed: a number, string, boolean or array of them)");
    if (path == "initial.seed")
      throw SceneError(reader.where(value) + ": " + name + ": \"initial.seed\" is chosen by " +
                       name.substr(0, name.find('.')) +
                       ".seeds; "
                       "give the seeds there (seeds = [" +
                       text + "])");
    out.push_back(path + "=" + text);
    origins.push_back(reader.where(value));
  }
}

SweepAxis read_axis(TableReader& vary, const toml::table& raw) {
  SweepAxis axis;
  vary.allow({"key", "values"});
  vary.finish();  // a misspelt key first: "values" missing is then no surprise
  axis.key = vary.required_string("key");
  if (axis.key.empty() || axis.key.front() == '.' || axis.key.back() == '.' ||
      axis.key.find("..") != std::string::npos || axis.key.find('=') != std::string::npos)
    vary.fail("key", "is not a dotted scene key (e.g. \"species.fines.diameter\", as for --set)");
  if (axis.key == "initial.seed")
    vary.fail("key", "cannot be varied here: the seeds are sweep.seeds (e.g. seeds = [1, 2, 3])");
  const std::string allowed =
      "(allowed: a non-empty array of distinct numbers, strings, booleans or arrays)";
  if (!vary.has("values")) vary.fail("values", "is missing " + allowed);
  const auto* array = raw.get("values")->as_array();
  if (array == nullptr) vary.fail("values", "is not an array " + allowed);
  if (array->empty()) vary.fail("values", "is empty " + allowed);
  for (const toml::node& element : *array) {
    SweepValue value;
    value.text = override_text(element);
    if (value.text.empty())
      vary.fail("values", "holds " + value_text(element) + ", which --set cannot take " + allowed);
    for (const SweepValue& other : axis.values)
      if (other.text == value.text)
        vary.fail("values", "holds " + value.text + " twice " + allowed);
    const auto* s = element.as_string();
    value.label = s != nullptr ? s->get() : value.text;
    value.number = number_of(element);
    value.where = vary.where(element);
    axis.values.push_back(std::move(value));
  }
  return axis;
}

}  // namespace

void flatten_scene_changes(const toml::table& table, const TableReader& reader,
                           const std::string& name, std::vector<std::string>& out,
                           std::vector<std::string>& origins) {
  flatten_set(table, "", reader, name, out, origins);
}

bool SweepAxis::numeric() const {
  return std::all_of(values.begin(), values.end(),
                     [](const SweepValue& v) { return v.number.has_value(); });
}

std::size_t SweepSpec::group_count() const {
  std::size_t count = 1;
  for (const SweepAxis& axis : axes) count *= axis.values.size();
  return count;
}

std::vector<SweepCase> SweepSpec::cases() const {
  std::vector<SweepCase> out;
  const std::size_t groups = group_count();
  for (std::size_t group = 0; group < groups; ++group) {
    // Mixed radix, first axis slowest.
    std::vector<std::size_t> choice(axes.size());
    std::size_t rest = group;
    for (std::size_t a = axes.size(); a-- > 0;) {
      choice[a] = rest % axes[a].values.size();
      rest /= axes[a].values.size();
    }
    for (const std::uint64_t seed : seeds) {
      SweepCase c;
      c.index = out.size();
      c.group = group;
      c.choice = choice;
      c.seed = seed;
      c.overrides = fixed;
      c.origins = fixed_origins;
      c.origins.resize(c.overrides.size());
      for (std::size_t a = 0; a < axes.size(); ++a) {
        const SweepValue& value = axes[a].values[choice[a]];
        if (axes[a].label_only) {
          c.overrides.insert(c.overrides.end(), value.sets.begin(), value.sets.end());
          c.origins.insert(c.origins.end(), value.set_origins.begin(), value.set_origins.end());
          c.origins.resize(c.overrides.size());
          continue;
        }
        c.overrides.push_back(axes[a].key + "=" + value.text);
        c.origins.push_back(value.where);
      }
      out.push_back(std::move(c));
    }
  }
  return out;
}

std::string SweepSpec::describe_group(std::size_t group) const {
  std::string text;
  for (std::size_t a = axes.size(); a-- > 0;) {
    const SweepAxis& axis = axes[a];
    const std::string item = axis.key + "=" + axis.values[group % axis.values.size()].label;
    text = text.empty() ? item : item + ", " + text;
    group /= axis.values.size();
  }
  return text;
}

SweepSpec read_sweep(const std::string& path) {
  std::error_code missing;
  if (!std::filesystem::exists(path, missing)) throw SceneError(path + ": cannot open the sweep file");
  const std::string document = without_bom(read_regular_file(path, "the sweep file", std::size_t{64} << 20));
  toml::table root;
  try {
    root = toml::parse(std::string_view(document), std::string_view(path));
  } catch (const toml::parse_error& e) {
    throw SceneError(path + ":" + std::to_string(e.source().begin.line) + ":" +
                     std::to_string(e.source().begin.column) +
                     ": not valid TOML: " + std::string(e.description()));
  }
  TableReader top(root, path, "");
  const toml::table* raw = root.get_as<toml::table>("sweep");
  std::optional<TableReader> sweep = top.table("sweep");
  top.finish();
  if (!sweep || raw == nullptr)
    throw SceneError(
        path +
        ": no [sweep] table; a sweep file starts with [sweep] and scene = \"SCENE.toml\" "
        "(see scenarios/sweep/SWEEPS.md)");

  SweepSpec spec;
  spec.file = path;
  const std::string scene = sweep->required_string("scene");
  const fs::path folder = fs::path(path).parent_path();
  spec.scene = fs::path(scene).is_absolute() || folder.empty() ? scene : (folder / scene).string();
  if (!fs::exists(spec.scene))
    sweep->fail("scene", "names no file (looked for " + spec.scene + ")");
  spec.out = sweep->string("out", fs::path(path).stem().string() + ".out");
  if (spec.out.empty()) sweep->fail("out", "is empty (allowed: a directory path)");
  spec.seeds = read_seeds(*sweep, *raw, 1,
                          "(allowed: a non-empty array of distinct integers >= 0, e.g. seeds = [1, 2, 3])");

  if (sweep->has("set")) {
    const auto* set = raw->get("set")->as_table();
    if (set == nullptr)
      sweep->fail("set",
                  "is not a table (write set = { \"time.end\" = 1.0 } or a [sweep.set] section)");
    flatten_set(*set, "", *sweep, "sweep.set", spec.fixed, spec.fixed_origins);
  }
  std::vector<TableReader> vary = sweep->tables("vary");
  const toml::array* vary_raw = raw->get_as<toml::array>("vary");
  for (std::size_t k = 0; k < vary.size(); ++k) {
    SweepAxis axis = read_axis(vary[k], *vary_raw->get(k)->as_table());
    for (const SweepAxis& other : spec.axes)
      if (other.key == axis.key)
        vary[k].fail("key", "is varied twice (merge the two entries' values)");
    for (const std::string& assignment : spec.fixed)
      if (assignment.substr(0, assignment.find('=')) == axis.key)
        vary[k].fail("key", "is also in sweep.set (a key is either fixed or varied)");
    spec.axes.push_back(std::move(axis));
  }
  sweep->finish();
  return spec;
}

std::vector<std::uint64_t> read_seeds(TableReader& t, const toml::table& raw, std::size_t minimum,
                                      const std::string& allowed) {
  std::vector<std::uint64_t> seeds;
  if (!t.has("seeds")) return seeds;
  const auto* array = raw.get("seeds")->as_array();
  if (array == nullptr) t.fail("seeds", "is not an array " + allowed);
  if (array->size() < minimum)
    t.fail("seeds", (array->empty() ? std::string("is empty ")
                                    : "holds fewer than " + std::to_string(minimum) + " seeds ") +
                        allowed);
  for (const toml::node& element : *array) {
    const auto* i = element.as_integer();
    if (i == nullptr || i->get() < 0)
      t.fail("seeds", "holds " + value_text(element) + ", which is not an integer >= 0 " + allowed);
    const auto seed = static_cast<std::uint64_t>(i->get());
    if (std::find(seeds.begin(), seeds.end(), seed) != seeds.end())
      t.fail("seeds", "holds " + std::to_string(seed) + " twice " + allowed);
    seeds.push_back(seed);
  }
  return seeds;
}

}  // namespace carom
