#include "scenarios/scene/overrides.hpp"

#include <cctype>
#include <charconv>
#include <limits>
#include <vector>

#include "scenarios/scene/scene_reader.hpp"

namespace carom {

namespace {
std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

std::vector<std::string> split_path(std::string_view key) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (;;) {
    const std::size_t dot = key.find('.', start);
    parts.emplace_back(trim(key.substr(start, dot == std::string_view::npos ? dot : dot - start)));
    if (dot == std::string_view::npos) break;
    start = dot + 1;
  }
  return parts;
}

/// The value as a TOML node (a string when it is not valid TOML); `source`: the path its nodes
/// carry.
toml::table parse_value(std::string_view text, const std::string& source) {
  try {
    const std::string document = "value = " + std::string(text);
    toml::table holder = toml::parse(std::string_view(document), std::string_view(source));
    return holder;
  } catch (const toml::parse_error&) {
    toml::table holder;
    holder.insert("value", std::string(text));
    return holder;
  }
}

/// Strips the source positions of a parsed value, so messages say it came from the command line.
toml::table* as_table_step(toml::node* n) { return n ? n->as_table() : nullptr; }
}  // namespace

void apply_override(toml::table& scene, std::string_view assignment, const std::string& origin) {
  const std::string quoted = origin.empty() ? "--set " + std::string(assignment) : origin + ": " + std::string(assignment);
  const std::size_t equals = assignment.find('=');
  if (equals == std::string_view::npos)
    throw SceneError(quoted + ": expected key=value (e.g. --set collisions.default.e=0.9)");
  const std::string_view key = trim(assignment.substr(0, equals));
  const std::string_view value = trim(assignment.substr(equals + 1));
  if (key.empty() || value.empty())
    throw SceneError(quoted + ": expected key=value with a non-empty key and value");
  const std::vector<std::string> parts = split_path(key);
  for (const auto& p : parts)
    if (p.empty()) throw SceneError(quoted + ": the key has an empty component");

  toml::table* table = &scene;
  std::string walked;
  for (std::size_t k = 0; k + 1 < parts.size(); ++k) {
    const std::string& part = parts[k];
    walked += (walked.empty() ? "" : ".") + part;
    toml::node* next = table->get(part);
    if (next == nullptr) {
      table->insert(part, toml::table{});
      table = table->get(part)->as_table();
      continue;
    }
    if (auto* t = as_table_step(next)) {
      table = t;
      continue;
    }
    auto* array = next->as_array();
    if (array == nullptr || k + 2 > parts.size())
      throw SceneError(quoted + ": '" + walked + "' is a value, not a table");
    // Array of tables: the next component is an index or a name.
    const std::string& pick = parts[++k];
    toml::table* chosen = nullptr;
    std::size_t index = 0;
    const auto [end, error] = std::from_chars(pick.data(), pick.data() + pick.size(), index);
    if (error == std::errc() && end == pick.data() + pick.size()) {
      if (index < array->size()) chosen = array->get(index)->as_table();
      if (!chosen)
        throw SceneError(quoted + ": '" + walked + "' has no table number " + pick + " (it holds " +
                         std::to_string(array->size()) + ", counted from 0)");
    } else {
      for (auto& element : *array) {
        auto* t = element.as_table();
        if (t == nullptr) continue;
        if (const auto* name = t->get_as<std::string>("name"); name && name->get() == pick) chosen = t;
      }
      if (!chosen) throw SceneError(quoted + ": '" + walked + "' has no entry named \"" + pick + "\"");
    }
    walked += "." + pick;
    if (k + 1 >= parts.size()) throw SceneError(quoted + ": the key ends at a table, not a value");
    table = chosen;
  }
  toml::table holder = parse_value(value, origin.empty() ? std::string("--set") : origin);
  toml::node* parsed = holder.get("value");
  parsed->visit([&](auto& v) {
    using V = std::remove_cvref_t<decltype(v)>;
    if (origin.empty()) {
      // A fresh copy carries no source position: messages then say "set on the command line".
      V copy(v);
      table->insert_or_assign(parts.back(), std::move(copy));
    } else {
      // Moved, the value keeps its source (path = origin), which messages then name.
      table->insert_or_assign(parts.back(), std::move(v));
    }
  });
}

std::uint64_t parse_seed(std::string_view text) {
  constexpr auto largest = static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max());
  const std::string_view digits = trim(text);
  std::uint64_t seed = 0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), seed);
  const bool whole = !digits.empty() && std::isdigit(static_cast<unsigned char>(digits.front())) &&
                     error == std::errc() && end == digits.data() + digits.size();
  if (!whole || seed > largest)
    throw SceneError("--seed " + std::string(text) + ": a seed must be a non-negative integer, in [0, " +
                     std::to_string(largest) + "] (initial.seed)");
  return seed;
}

}  // namespace carom
