#include "scenarios/chart/chart_table.hpp"

#include <algorithm>
#include <cmath>

#include "scenarios/scene/scene_reader.hpp"

namespace carom {

namespace {

/// Column of `name` among the sweep's metrics, or nullopt.
std::optional<std::size_t> metric_column(const SweepTable& sweep, const std::string& name) {
  const auto it = std::find(sweep.metrics.begin(), sweep.metrics.end(), name);
  if (it == sweep.metrics.end()) return std::nullopt;
  return static_cast<std::size_t>(it - sweep.metrics.begin());
}

/// Why an observable cannot be compared: named in the chart file, absent from every summary.
std::string missing_observable(const ChartSpec& chart, std::size_t k, const SweepTable& sweep) {
  const ChartObservable& o = chart.observables[k];
  std::string message = o.where + ": chart.observable[" + std::to_string(k) + "].key = \"" + o.key +
                        "\" is not a number in any completed case's summary.json";
  const std::string guess = closest(o.key, sweep.metrics);
  if (!guess.empty()) message += "; did you mean \"" + guess + "\"?";
  message += " (allowed: the numbers summary.json holds, the columns of " + chart.out +
             "/summary.csv after `seed`, e.g.";
  std::size_t shown = 0;
  for (const std::string& m : sweep.metrics) {
    if (m.rfind("analysis.", 0) != 0 && m.rfind("collision_rate", 0) != 0 &&
        m.rfind("pressure", 0) != 0 && m != "mean_temperature")
      continue;
    message += (shown ? ", " : " ") + m;
    if (++shown == 6) break;
  }
  return message + ")";
}

}  // namespace

ChartTable chart_table(const ChartSpec& chart, const SweepTable& sweep) {
  ChartTable table;
  const std::size_t V = chart.variants.size(), K = chart.observables.size();
  const std::optional<std::size_t> end_time = metric_column(sweep, "end_time");
  std::vector<std::optional<std::size_t>> columns;
  for (const ChartObservable& o : chart.observables) columns.push_back(metric_column(sweep, o.key));

  std::vector<std::vector<double>> costs(V);
  std::vector<std::vector<std::vector<double>>> values(V, std::vector<std::vector<double>>(K));
  table.variants.resize(V);
  for (const CaseRow& row : sweep.cases) {
    ChartCaseRow c;
    c.index = row.c.index;
    c.variant = row.c.group;
    c.seed = row.c.seed;
    c.status = row.result.status;
    c.cpu_seconds = row.result.cpu_seconds;
    c.simulated_seconds = end_time ? row.metrics[*end_time] : kMissing;
    const bool completed = c.status == "completed";
    c.cost = completed && c.simulated_seconds > 0 && c.cpu_seconds > 0
                 ? c.cpu_seconds / c.simulated_seconds
                 : kMissing;
    for (std::size_t k = 0; k < K; ++k)
      c.observables.push_back(columns[k] ? row.metrics[*columns[k]] : kMissing);
    ChartVariantRow& v = table.variants[c.variant];
    ++v.cases;
    if (completed) {
      ++v.completed;
      costs[c.variant].push_back(c.cost);
      for (std::size_t k = 0; k < K; ++k) values[c.variant][k].push_back(c.observables[k]);
    }
    table.cases.push_back(std::move(c));
  }

  for (std::size_t v = 0; v < V; ++v) {
    table.variants[v].cost = seed_statistics(costs[v]);
    for (std::size_t k = 0; k < K; ++k)
      table.variants[v].observables.push_back({seed_statistics(values[v][k]), {}, false, {}});
  }
  table.problems.assign(K, "");
  table.cheapest.assign(K, std::nullopt);
  for (std::size_t k = 0; k < K; ++k) {
    const ChartObservable& o = chart.observables[k];
    const SeedStatistics& reference = table.variants[chart.reference].observables[k].statistics;
    bool found = false, any_completed = false;
    for (const ChartVariantRow& v : table.variants) {
      found |= v.observables[k].statistics.count > 0;
      any_completed |= v.completed > 0;
    }
    if (any_completed && !found) table.problems[k] = missing_observable(chart, k, sweep);
    std::vector<ChartPoint> points;
    for (std::size_t v = 0; v < V; ++v) {
      ChartObservableResult& r = table.variants[v].observables[k];
      r.error = error_against_reference(r.statistics, reference, o.measure, v == chart.reference);
      r.within_tolerance = std::abs(r.error.error) <= o.tolerance;
      points.push_back({table.variants[v].cost.mean, std::abs(r.error.error), r.error.noise});
    }
    const std::vector<FrontMembership> front = pareto_front(points);
    for (std::size_t v = 0; v < V; ++v) table.variants[v].observables[k].front = front[v];
    table.cheapest[k] = cheapest_within(points, o.tolerance, chart.reference);
  }
  return table;
}

}  // namespace carom
