#include "scenarios/scene/scene_reader.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>

namespace carom {

std::string format_number(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), x);
  return std::string(buffer, result.ptr);
}

std::string Range::describe() const {
  std::string text = lower_open ? "(" : "[";
  text += std::isinf(lower) ? "-inf" : format_number(lower);
  text += ", ";
  text += std::isinf(upper) ? "inf" : format_number(upper);
  text += upper_open ? ")" : "]";
  return text;
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::string closest(std::string_view word, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_distance = std::numeric_limits<std::size_t>::max();
  for (const std::string& c : candidates) {
    const std::size_t d = edit_distance(word, c);
    // Close enough: at most half the longer word changed (grid_ratio -> grid_level_ratio).
    if (2 * d <= std::max({word.size(), c.size(), std::size_t{4}}) && d < best_distance) {
      best_distance = d;
      best = c;
    }
  }
  return best;
}

namespace {
/// A value as TOML, numbers in their shortest exact form (toml++'s own printer writes
/// 0.10000000000000001 for 0.1).
void write_value(const toml::node& node, std::string& text) {
  if (const auto* v = node.as_floating_point()) {
    text += format_number(v->get());
  } else if (const auto* v = node.as_integer()) {
    text += std::to_string(v->get());
  } else if (const auto* v = node.as_string()) {
    text += "\"" + v->get() + "\"";
  } else if (const auto* v = node.as_boolean()) {
    text += v->get() ? "true" : "false";
  } else if (const auto* a = node.as_array()) {
    text += "[";
    for (std::size_t i = 0; i < a->size(); ++i) {
      text += i ? ", " : "";
      write_value((*a)[i], text);
    }
    text += "]";
  } else if (const auto* t = node.as_table()) {
    text += "{ ";
    bool first = true;
    for (const auto& [key, value] : *t) {
      text += first ? "" : ", ";
      text += std::string(key.str()) + " = ";
      write_value(value, text);
      first = false;
    }
    text += " }";
  } else {
    text += "?";
  }
}
}  // namespace

std::string value_text(const toml::node& node) {
  std::string text;
  write_value(node, text);
  if (text.size() > 80) text = text.substr(0, 77) + "...";
  return text;
}

TableReader::TableReader(const toml::table& table, std::string file, std::string path)
    : table_(&table), file_(std::move(file)), path_(std::move(path)) {}

std::string TableReader::where(const toml::node& node) const {
  const auto line = node.source().begin.line;
  if (line == 0) return file_ + " (set on the command line)";
  // A value set by a sweep file carries the place it was written (overrides.hpp).
  if (const auto& path = node.source().path; path && *path != file_) return *path + " (for " + file_ + ")";
  return file_ + ":" + std::to_string(line);
}

std::string TableReader::where() const { return where(*table_); }

bool TableReader::has(std::string_view key) {
  return node(key) != nullptr;
}

void TableReader::allow(std::initializer_list<std::string_view> keys) {
  for (auto key : keys) known_.emplace_back(key);
}

const toml::node* TableReader::node(std::string_view key) {
  if (std::find(known_.begin(), known_.end(), key) == known_.end()) known_.emplace_back(key);
  return table_->get(key);
}

void TableReader::fail(std::string_view key, const std::string& problem) const {
  const toml::node* n = table_->get(key);
  if (n == nullptr) throw SceneError(where() + ": " + key_path(key) + ": " + problem);
  throw SceneError(where(*n) + ": " + key_path(key) + " = " + value_text(*n) + " " + problem);
}

void TableReader::fail_table(const std::string& problem) const {
  throw SceneError(where() + ": " + (path_.empty() ? std::string("scene") : path_) + ": " + problem);
}

double TableReader::as_number(std::string_view key, const toml::node& n, const Range& range) const {
  double x;
  if (const auto* f = n.as_floating_point()) x = f->get();
  else if (const auto* i = n.as_integer()) x = static_cast<double>(i->get());
  else fail(key, "is not a number (expected " + range.meaning + ", allowed range " + range.describe() + ")");
  if (!std::isfinite(x))
    fail(key, "is not a finite number (expected " + range.meaning + ", allowed range " + range.describe() + ")");
  if (!range.contains(x))
    fail(key, "is outside the allowed range " + range.describe() + " (" + range.meaning + ")");
  return x;
}

double TableReader::number(std::string_view key, double fallback, const Range& range) {
  const toml::node* n = node(key);
  return n ? as_number(key, *n, range) : fallback;
}

double TableReader::number(std::string_view key, const Range& range) {
  const toml::node* n = node(key);
  if (!n) fail(key, "is missing (" + range.meaning + ", allowed range " + range.describe() + ")");
  return as_number(key, *n, range);
}

std::optional<double> TableReader::optional_number(std::string_view key, const Range& range) {
  const toml::node* n = node(key);
  if (!n) return std::nullopt;
  return as_number(key, *n, range);
}

std::int64_t TableReader::integer(std::string_view key, std::int64_t fallback, std::int64_t lower,
                                  std::int64_t upper, const std::string& meaning) {
  const toml::node* n = node(key);
  if (!n) return fallback;
  const std::string allowed = "an integer in [" + std::to_string(lower) + ", " + std::to_string(upper) + "]";
  const auto* i = n->as_integer();
  if (!i) fail(key, "is not an integer (" + meaning + ", allowed: " + allowed + ")");
  if (i->get() < lower || i->get() > upper) fail(key, "is outside the allowed range: " + allowed + " (" + meaning + ")");
  return i->get();
}

bool TableReader::boolean(std::string_view key, bool fallback) {
  const toml::node* n = node(key);
  if (!n) return fallback;
  const auto* b = n->as_boolean();
  if (!b) fail(key, "is not a boolean (allowed: true or false)");
  return b->get();
}

namespace {
std::string choice_list(const std::vector<std::string>& choices) {
  std::string text;
  for (const auto& c : choices) text += (text.empty() ? "\"" : ", \"") + c + "\"";
  return text;
}
}  // namespace

std::string TableReader::string(std::string_view key, const std::string& fallback,
                                const std::vector<std::string>& choices) {
  const toml::node* n = node(key);
  if (!n) return fallback;
  const auto* s = n->as_string();
  const std::string allowed = choices.empty() ? std::string("a string") : "one of " + choice_list(choices);
  if (!s) fail(key, "is not a string (allowed: " + allowed + ")");
  if (!choices.empty() && std::find(choices.begin(), choices.end(), s->get()) == choices.end()) {
    const std::string guess = closest(s->get(), choices);
    fail(key, "is not allowed (allowed: " + allowed + ")" + (guess.empty() ? "" : "; did you mean \"" + guess + "\"?"));
  }
  return s->get();
}

std::string TableReader::required_string(std::string_view key, const std::vector<std::string>& choices) {
  if (!table_->get(key)) {
    node(key);
    fail(key, "is missing" + (choices.empty() ? std::string() : " (allowed: one of " + choice_list(choices) + ")"));
  }
  return string(key, "", choices);
}

Vec3 TableReader::vector3(std::string_view key, const Vec3& fallback, const Range& range) {
  const toml::node* n = node(key);
  if (!n) return fallback;
  const auto* a = n->as_array();
  if (!a || a->size() != 3)
    fail(key, "is not an array of three numbers (" + range.meaning + ", each in " + range.describe() + ")");
  Vec3 v;
  for (int k = 0; k < 3; ++k) {
    const toml::node& c = *a->get(static_cast<std::size_t>(k));
    double x;
    if (const auto* f = c.as_floating_point()) x = f->get();
    else if (const auto* i = c.as_integer()) x = static_cast<double>(i->get());
    else fail(key, "has a component that is not a number (" + range.meaning + ")");
    if (!std::isfinite(x)) fail(key, "has a component that is not finite (" + range.meaning + ")");
    if (!range.contains(x))
      fail(key, "has component " + std::string(1, "xyz"[k]) + " = " + format_number(x) +
                    " outside the allowed range " + range.describe() + " (" + range.meaning + ")");
    v[k] = x;
  }
  return v;
}

Vec3 TableReader::required_vector3(std::string_view key, const Range& range) {
  if (!table_->get(key)) {
    node(key);
    fail(key, "is missing (" + range.meaning + ": three numbers)");
  }
  return vector3(key, Vec3::Zero(), range);
}

std::vector<Vec3> TableReader::required_vector3_list(std::string_view key, std::size_t least,
                                                     const Range& range) {
  const std::string expected = "an array of at least " + std::to_string(least) +
                               " points [x, y, z] (" + range.meaning + ", each number in " +
                               range.describe() + ")";
  const toml::node* n = node(key);
  if (!n) fail(key, "is missing (" + expected + ")");
  const auto* a = n->as_array();
  if (!a) fail(key, "is not " + expected);
  std::vector<Vec3> out;
  for (const toml::node& entry : *a) {
    const std::string which = "point " + std::to_string(out.size() + 1);
    const auto* point = entry.as_array();
    if (!point || point->size() != 3)
      fail(key, "has " + which + " that is not three numbers (" + expected + ")");
    Vec3 v;
    for (int k = 0; k < 3; ++k) {
      const toml::node& c = *point->get(static_cast<std::size_t>(k));
      double x;
      if (const auto* f = c.as_floating_point())
        x = f->get();
      else if (const auto* i = c.as_integer())
        x = static_cast<double>(i->get());
      else
        fail(key, "has " + which + " with a component that is not a number (" + expected + ")");
      if (!std::isfinite(x) || !range.contains(x))
        fail(key, "has " + which + " with component " + std::string(1, "xyz"[k]) + " = " +
                      format_number(x) + " outside the allowed range " + range.describe() + " (" +
                      range.meaning + ")");
      v[k] = x;
    }
    out.push_back(v);
  }
  if (out.size() < least)
    fail(key, "has " + std::to_string(out.size()) + " points; at least " + std::to_string(least) +
                  " are needed (" + expected + ")");
  return out;
}

std::vector<double> TableReader::numbers(std::string_view key, const Range& range) {
  std::vector<double> out;
  const toml::node* n = node(key);
  if (!n) return out;
  const auto* a = n->as_array();
  if (!a)
    fail(key,
         "is not an array of numbers (" + range.meaning + ", each in " + range.describe() + ")");
  for (const toml::node& c : *a) {
    double x;
    if (const auto* f = c.as_floating_point())
      x = f->get();
    else if (const auto* i = c.as_integer())
      x = static_cast<double>(i->get());
    else
      fail(key, "has an entry that is not a number (" + range.meaning + ")");
    if (!std::isfinite(x)) fail(key, "has an entry that is not finite (" + range.meaning + ")");
    if (!range.contains(x))
      fail(key, "has entry " + std::to_string(out.size() + 1) + " = " + format_number(x) +
                    " outside the allowed range " + range.describe() + " (" + range.meaning + ")");
    out.push_back(x);
  }
  return out;
}

std::vector<std::string> TableReader::strings(std::string_view key) {
  std::vector<std::string> out;
  const toml::node* n = node(key);
  if (!n) return out;
  const auto* a = n->as_array();
  if (!a) fail(key, "is not an array of strings");
  for (const toml::node& c : *a) {
    const auto* s = c.as_string();
    if (!s) fail(key, "is not an array of strings");
    out.push_back(s->get());
  }
  return out;
}

std::optional<TableReader> TableReader::table(std::string_view key) {
  const toml::node* n = node(key);
  if (!n) return std::nullopt;
  const auto* t = n->as_table();
  if (!t) fail(key, "is not a table");
  return TableReader(*t, file_, key_path(key));
}

std::vector<TableReader> TableReader::tables(std::string_view key) {
  std::vector<TableReader> out;
  const toml::node* n = node(key);
  if (!n) return out;
  const auto* a = n->as_array();
  if (!a) fail(key, "is not an array of tables (write [[" + key_path(key) + "]])");
  for (std::size_t i = 0; i < a->size(); ++i) {
    const auto* t = a->get(i)->as_table();
    if (!t) fail(key, "is not an array of tables (write [[" + key_path(key) + "]])");
    out.emplace_back(*t, file_, key_path(key) + "[" + std::to_string(i) + "]");
  }
  return out;
}

std::vector<std::string> TableReader::keys() {
  std::vector<std::string> out;
  for (auto&& [key, value] : *table_) out.emplace_back(key.str());
  for (const auto& k : out) node(k);
  return out;
}

void TableReader::finish() const {
  for (auto&& [key, value] : *table_) {
    const std::string name(key.str());
    if (std::find(known_.begin(), known_.end(), name) != known_.end()) continue;
    const std::string guess = closest(name, known_);
    std::string message = where(value) + ": unknown key '" + key_path(name) + "'";
    if (!guess.empty()) message += "; did you mean '" + key_path(guess) + "'?";
    else {
      message += " (known keys here:";
      for (const auto& k : known_) message += " " + k;
      message += ")";
    }
    throw SceneError(message);
  }
}

}  // namespace carom
