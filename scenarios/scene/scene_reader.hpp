#pragma once
/// Checked reading of one TOML table of a scene: typed values with ranges, and unknown keys.
///
/// Every accessor records its key as known; `finish()` then rejects whatever the table holds
/// that nobody asked for, suggesting the closest known key. Every message names the file, the
/// line, the dotted key, the value and what is allowed, e.g.
///   gas.toml:14: collisions.default.e = 1.2 is outside the allowed range [0, 1] (normal restitution)
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "core/vec3.hpp"

namespace carom {

/// A mistake in a scene or on the command line: the run must not start (exit code 2).
class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// An allowed interval of a number, and what the number means (for messages).
struct Range {
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
  bool lower_open = false;  ///< true: the lower bound itself is not allowed.
  bool upper_open = false;
  std::string meaning;      ///< e.g. "normal restitution".

  bool contains(double x) const {
    return (lower_open ? x > lower : x >= lower) && (upper_open ? x < upper : x <= upper);
  }
  /// "[0, 1]", "(0, inf)", ...
  std::string describe() const;

  static Range positive(std::string meaning) { return {0.0, std::numeric_limits<double>::infinity(), true, true, std::move(meaning)}; }
  static Range non_negative(std::string meaning) { return {0.0, std::numeric_limits<double>::infinity(), false, true, std::move(meaning)}; }
  static Range any(std::string meaning) { return {-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(), true, true, std::move(meaning)}; }
  static Range closed(double lo, double hi, std::string meaning) { return {lo, hi, false, false, std::move(meaning)}; }
};

/// Shortest text that reads back as the same double.
std::string format_number(double x);
/// Levenshtein distance (for "did you mean" suggestions).
std::size_t edit_distance(std::string_view a, std::string_view b);
/// The candidate closest to `word`, or "" when none is reasonably close.
std::string closest(std::string_view word, const std::vector<std::string>& candidates);

class TableReader {
 public:
  /// `file`: name used in messages; `path`: dotted path of this table ("" at the root).
  TableReader(const toml::table& table, std::string file, std::string path);

  const std::string& file() const { return file_; }
  const std::string& path() const { return path_; }
  /// Dotted path of a key in this table.
  std::string key_path(std::string_view key) const { return path_.empty() ? std::string(key) : path_ + "." + std::string(key); }
  /// "file:line" of a node, "file (set on the command line)" for values added by --set, or
  /// "sweep.toml:12 (for file)" for values a sweep file set (apply_override's origin).
  std::string where(const toml::node& node) const;
  /// "file:line" of this table.
  std::string where() const;
  /// "file:line" of a key's value (of this table when the key is absent).
  std::string where_key(std::string_view key) const {
    const toml::node* n = table_->get(key);
    return n != nullptr ? where(*n) : where();
  }

  /// True when the key is present and holds a string (a key that may be a string or a table).
  bool is_string(std::string_view key) const {
    const toml::node* n = table_->get(key);
    return n != nullptr && n->is_string();
  }
  /// True when the key is present (and records it as known).
  bool has(std::string_view key);
  /// Records keys as known without reading them.
  void allow(std::initializer_list<std::string_view> keys);

  /// A number (integer or float) with a default.
  double number(std::string_view key, double fallback, const Range& range);
  /// A number that must be present.
  double number(std::string_view key, const Range& range);
  /// An optional number.
  std::optional<double> optional_number(std::string_view key, const Range& range);
  /// An integer in [lower, upper].
  std::int64_t integer(std::string_view key, std::int64_t fallback, std::int64_t lower, std::int64_t upper,
                       const std::string& meaning);
  bool boolean(std::string_view key, bool fallback);
  /// A string; when `choices` is not empty it must be one of them.
  std::string string(std::string_view key, const std::string& fallback, const std::vector<std::string>& choices = {});
  std::string required_string(std::string_view key, const std::vector<std::string>& choices = {});
  /// Three numbers, each in `range`.
  Vec3 vector3(std::string_view key, const Vec3& fallback, const Range& range);
  Vec3 required_vector3(std::string_view key, const Range& range);
  /// An array of points, each three numbers in `range` (`key = [[x, y, z], ...]`); it must be
  /// present and hold at least `least` of them.
  std::vector<Vec3> required_vector3_list(std::string_view key, std::size_t least,
                                          const Range& range);
  /// An array of strings.
  std::vector<std::string> strings(std::string_view key);
  /// An array of numbers, each in `range` (empty when absent).
  std::vector<double> numbers(std::string_view key, const Range& range);
  /// A sub-table (inline or standard), or nullopt when absent.
  std::optional<TableReader> table(std::string_view key);
  /// An array of tables (`[[key]]`); empty when absent.
  std::vector<TableReader> tables(std::string_view key);

  /// Every key of the table (sorted) (all recorded as known): for tables keyed by name.
  std::vector<std::string> keys();

  /// Throws for the first key that no accessor asked about.
  void finish() const;

  /// Throws SceneError "where: path.key = value problem".
  [[noreturn]] void fail(std::string_view key, const std::string& problem) const;
  /// Throws SceneError "where(table): path: problem".
  [[noreturn]] void fail_table(const std::string& problem) const;

 private:
  const toml::node* node(std::string_view key);
  double as_number(std::string_view key, const toml::node& n, const Range& range) const;

  const toml::table* table_;
  std::string file_;
  std::string path_;
  std::vector<std::string> known_;
};

/// Text of a TOML value as written in a scene ("1.2", "\"tc\"", "[1, 2]").
std::string value_text(const toml::node& node);

}  // namespace carom
