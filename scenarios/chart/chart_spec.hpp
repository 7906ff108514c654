#pragma once
/// A chart file: one scene run as several variants (methods and their accuracy knobs), each
/// over the same seeds, with the observables to compare against a reference variant.
///
///   [chart]
///   scene = "dilute_gas.toml"          # relative to the chart file's folder
///   out = "dilute_gas_chart.out"       # default: the chart file's stem + ".out"
///   seeds = [1, 2, 3]                  # at least two: the standard errors need them
///   reference = "event_driven"         # the name of the most exact variant
///   set = { "time.end" = 20.0 }        # optional: changes made to every variant
///   [[chart.observable]]
///   key = "analysis.collision_frequency.sphere-sphere"   # a number in summary.json
///   tolerance = 0.02                   # the error a user accepts
///   error = "relative"                 # or "absolute" (in the observable's unit)
///   [[chart.variant]]
///   name = "event_driven"
///   set = { "method.kind" = "event_driven" }
///
/// CHARTS.md documents every key. Every mistake is a SceneError naming the file, the line, the
/// key and what is allowed, like the scene reader's.
#include <cstdint>
#include <string>
#include <vector>

#include "scenarios/sweep/sweep_spec.hpp"

namespace carom {

/// How an observable's error against the reference is measured.
enum class ErrorMeasure {
  Relative,  ///< (variant mean - reference mean) / |reference mean|: dimensionless.
  Absolute,  ///< variant mean - reference mean: in the observable's own unit.
};

/// One number of summary.json compared between the variants.
struct ChartObservable {
  std::string key;                                ///< Dotted path in summary.json.
  double tolerance = 0;                           ///< Largest acceptable |error|, in `measure`.
  ErrorMeasure measure = ErrorMeasure::Relative;  ///< How the error is expressed.
  std::string where;                              ///< "chart.toml:LINE" of its key.
};

/// One way to run the scene: a name and its scene changes.
struct ChartVariant {
  std::string name;                  ///< Unique label (tables, plots, report).
  std::vector<std::string> sets;     ///< "key=value" for --set, in file order.
  std::vector<std::string> origins;  ///< Per change: "chart.toml:LINE" of its value.
  std::string where;                 ///< "chart.toml:LINE" of its name.
};

/// A chart file read and checked.
struct ChartSpec {
  std::string file;                          ///< The chart file as given.
  std::string scene;                         ///< Path of the scene (relative paths resolved).
  std::string out;                           ///< Output directory.
  std::vector<std::uint64_t> seeds;          ///< Every variant runs once per seed.
  std::vector<std::string> fixed;            ///< "key=value" from chart.set, for every variant.
  std::vector<std::string> fixed_origins;    ///< Per fixed change: "chart.toml:LINE".
  std::vector<ChartVariant> variants;        ///< In file order (group order of the sweep).
  std::size_t reference = 0;                 ///< Index of the reference variant.
  std::vector<ChartObservable> observables;  ///< In file order.
};

/// Reads and checks a chart file. Throws SceneError for anything wrong in it.
ChartSpec read_chart(const std::string& path);

/// The sweep that runs a chart: one label axis "variant" (each value its variant's changes),
/// the chart's seeds and fixed changes; case k is variant k / seeds, seed k % seeds.
SweepSpec chart_sweep(const ChartSpec& chart);

}  // namespace carom
