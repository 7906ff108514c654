#pragma once
/// A sweep file: one scene run over the cartesian product of scene-key values, once per seed.
///
///   [sweep]
///   scene = "fines_bed.toml"          # relative to the sweep file's folder
///   out = "fines_sweep.out"           # default: the sweep file's stem + ".out" (current directory)
///   seeds = [1, 2]                    # default: the scene's own initial.seed
///   set = { "time.end" = 1.0 }        # fixed changes for every case (dotted keys, as --set)
///   [[sweep.vary]]
///   key = "species.fines.diameter"
///   values = [3.3e-4, 2.5e-4]
///
/// Cases are numbered from 0: the first vary entry changes slowest, the seed fastest, so the
/// cases of one combination of varied values (a "group") are consecutive. SWEEPS.md documents
/// every key. Every mistake is a SceneError naming the file, the line, the key and what is
/// allowed, like the scene reader's.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "scenarios/scene/scene_reader.hpp"

namespace carom {

/// One value a varied key takes.
struct SweepValue {
  std::string text;   ///< As TOML, passed to --set ("0.00033", "\"kick\"", "[0, 0, -9.81]").
  std::string label;  ///< As shown in tables: text, strings without their quotes.
  std::optional<double> number;  ///< The value when it is a number (integer or float).
  std::string where;  ///< "sweep.toml:LINE" of the value, for the scene's messages about it.
  /// Of a label axis only: the "key=value" changes this value stands for, and per change the
  /// "file:LINE" where it is written (a chart's variant, scenarios/chart/CHARTS.md).
  std::vector<std::string> sets, set_origins;
};

/// A `[[sweep.vary]]` entry: a scene key and the values it takes.
struct SweepAxis {
  std::string key;                 ///< Dotted scene key, as for --set.
  std::vector<SweepValue> values;  ///< At least one, no two alike.
  /// True for a label axis (`carom chart`'s variants): `key` only names the column, and a case
  /// gets each chosen value's `sets` instead of key=value. Sweep files never make one.
  bool label_only = false;
  /// True when every value is a number (tables store the axis as numbers, else as text).
  bool numeric() const;
};

/// One run of the scene: its overrides and seed.
struct SweepCase {
  std::size_t index = 0;               ///< 0-based case number (directory cases/NNNN).
  std::size_t group = 0;               ///< Index of its combination of varied values.
  std::vector<std::size_t> choice;     ///< Per axis: index into its values.
  std::uint64_t seed = 1;              ///< Passed as --seed.
  std::vector<std::string> overrides;  ///< "key=value": the fixed set, then the varied keys.
  std::vector<std::string> origins;    ///< Per override: "sweep.toml:LINE" where it is written.
};

/// A sweep file read and checked.
struct SweepSpec {
  std::string file;                  ///< The sweep file as given (for messages).
  std::string scene;                 ///< Path of the scene file (relative paths resolved).
  std::string out;                   ///< Output directory.
  std::vector<std::string> fixed;    ///< "key=value" from sweep.set, in file order.
  std::vector<std::string> fixed_origins;  ///< Per fixed entry: "sweep.toml:LINE" of its value.
  std::vector<SweepAxis> axes;       ///< The vary entries, in file order.
  std::vector<std::uint64_t> seeds;  ///< Empty: the scene's own seed (filled in by the runner).

  /// Number of combinations of varied values (1 when nothing varies).
  std::size_t group_count() const;
  /// Every case, in case order (needs seeds filled in).
  std::vector<SweepCase> cases() const;
  /// "key=label, key=label" of a group (for progress lines and messages).
  std::string describe_group(std::size_t group) const;
};

/// Flattens a table of scene changes (`sweep.set`, a chart variant's `set`) into "key=value"
/// for --set, nested tables giving dotted keys, and per change the "file:LINE" of its value.
/// `name`: the table's dotted name, for messages. Throws SceneError for a value --set cannot
/// take and for `initial.seed` (seeds are listed apart).
void flatten_scene_changes(const toml::table& table, const TableReader& reader,
                           const std::string& name, std::vector<std::string>& out,
                           std::vector<std::string>& origins);

/// The `seeds` array of table `t` (`raw`: the same table): distinct integers >= 0, at least
/// `minimum` of them; `allowed` ends each error (what the key takes, with an example). Empty
/// when the key is missing. Throws SceneError naming the file, line and key.
std::vector<std::uint64_t> read_seeds(TableReader& t, const toml::table& raw, std::size_t minimum,
                                      const std::string& allowed);

/// Reads and checks a sweep file. Throws SceneError for anything wrong in it.
SweepSpec read_sweep(const std::string& path);

}  // namespace carom
