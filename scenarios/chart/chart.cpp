#include "scenarios/chart/chart.hpp"

#include <filesystem>
#include <iostream>

#include "scenarios/chart/chart_report.hpp"
#include "scenarios/chart/chart_spec.hpp"
#include "scenarios/chart/chart_table.hpp"
#include "scenarios/run/run.hpp"
#include "scenarios/sweep/sweep.hpp"
#include "scenarios/sweep/sweep_mpi.hpp"

namespace carom {

namespace fs = std::filesystem;

namespace {

/// One line per observable: the cheapest variant within its tolerance.
void print_conclusions(const ChartSpec& chart, const ChartTable& table) {
  for (std::size_t k = 0; k < chart.observables.size(); ++k) {
    const ChartObservable& o = chart.observables[k];
    std::cout << "carom chart: " << o.key << ": ";
    if (!table.problems[k].empty()) {
      std::cout << "not compared\n";
    } else if (const auto best = table.cheapest[k]) {
      const ChartVariantRow& row = table.variants[*best];
      std::cout << "cheapest within " << rounded(o.tolerance)
                << (o.measure == ErrorMeasure::Relative ? " (relative)" : "") << ": "
                << chart.variants[*best].name << ", " << rounded(row.cost.mean)
                << " CPU s per simulated s, error " << rounded(row.observables[k].error.error)
                << " ± " << rounded(row.observables[k].error.uncertainty, 2) << "\n";
    } else {
      std::cout << "no variant but the reference within " << rounded(o.tolerance) << "\n";
    }
  }
}

}  // namespace

int run_chart(const ChartOptions& options) {
  ChartSpec chart;
  try {
    chart = read_chart(options.file);
  } catch (const SceneError& e) {
    if (first_launched_process()) std::cerr << "carom chart: error: " << e.what() << "\n";
    return kExitUsage;
  }
  if (options.out) chart.out = *options.out;

  SweepOptions sweep;
  sweep.file = options.file;
  sweep.out = chart.out;
  sweep.jobs = options.jobs;
  sweep.quiet = options.quiet;
  sweep.retry_failed = options.retry_failed;
  sweep.dry_run = options.dry_run;
  sweep.spec = chart_sweep(chart);
  sweep.command = "carom chart";
  sweep.record_name = "chart.toml";
  const int code = run_sweep(sweep);
  // MPI is down again: only the first process gathers and writes.
  if (code == kExitUsage || options.dry_run || !first_launched_process()) return code;
  try {
    const SweepSpec spec = *sweep.spec;
    const ChartTable table = chart_table(chart, gather_sweep(spec, spec.cases()));
    write_chart(chart, table);
    if (!options.quiet) {
      print_conclusions(chart, table);
      std::cout << "carom chart: table in " << (fs::path(chart.out) / "chart.csv").string()
                << ", report in " << (fs::path(chart.out) / "report.md").string()
                << "; figures: /usr/bin/python3 scenarios/plots/chart_plot.py " << chart.out
                << std::endl;
    }
    bool missing = false;
    for (const std::string& problem : table.problems)
      if (!problem.empty()) {
        std::cerr << "carom chart: error: " << problem << "\n";
        missing = true;
      }
    if (missing && code != kExitInterrupted) return kExitUsage;
  } catch (const std::exception& e) {
    std::cerr << "carom chart: failed to write the chart: " << e.what() << "\n";
    return kExitFailure;
  }
  return code;
}

}  // namespace carom
