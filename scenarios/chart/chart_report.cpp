#include "scenarios/chart/chart_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "carom/version.hpp"
#include "core/hdf5.hpp"
#include "scenarios/run/summary.hpp"
#include "scenarios/scene/scene_reader.hpp"
#include "scenarios/sweep/sweep_report.hpp"

namespace carom {

namespace fs = std::filesystem;

namespace {

std::string cell(double x) {
  return std::isnan(x) ? std::string() : format_number(x);
}
std::string flag(bool b) {
  return b ? "true" : "false";
}

/// A dataset name for an observable ('/' would make a path).
const char* measure_name(ErrorMeasure m) {
  return m == ErrorMeasure::Relative ? "relative" : "absolute";
}

std::string variants_csv(const ChartSpec& chart, const ChartTable& table) {
  std::ostringstream csv;
  csv << "variant,reference,n_cases,n_completed,cost,cost_stderr";
  for (const ChartObservable& o : chart.observables)
    for (const char* column : {":mean", ":stderr", ":error", ":uncertainty", ":within_noise",
                               ":within_tolerance", ":pareto", ":pareto_within_noise"})
      csv << "," << csv_cell(o.key + column);
  csv << "\n";
  for (std::size_t v = 0; v < table.variants.size(); ++v) {
    const ChartVariantRow& row = table.variants[v];
    csv << csv_cell(chart.variants[v].name) << "," << flag(v == chart.reference) << "," << row.cases
        << "," << row.completed << "," << cell(row.cost.mean) << ","
        << cell(row.cost.standard_error);
    for (const ChartObservableResult& r : row.observables)
      csv << "," << cell(r.statistics.mean) << "," << cell(r.statistics.standard_error) << ","
          << cell(r.error.error) << "," << cell(r.error.uncertainty) << ","
          << flag(r.error.within_noise) << "," << flag(r.within_tolerance) << ","
          << flag(r.front.on_front) << "," << flag(r.front.dominated_within_noise);
    csv << "\n";
  }
  return csv.str();
}

std::string cases_csv(const ChartSpec& chart, const ChartTable& table) {
  std::ostringstream csv;
  csv << "case,variant,seed,status,cpu_seconds,simulated_seconds,cost";
  for (const ChartObservable& o : chart.observables) csv << "," << csv_cell(o.key);
  csv << "\n";
  for (const ChartCaseRow& c : table.cases) {
    csv << c.index << "," << csv_cell(chart.variants[c.variant].name) << "," << c.seed << ","
        << c.status << "," << cell(c.cpu_seconds) << "," << cell(c.simulated_seconds) << ","
        << cell(c.cost);
    for (const double x : c.observables) csv << "," << cell(x);
    csv << "\n";
  }
  return csv.str();
}

std::vector<std::int8_t> flags(const ChartTable& table, std::size_t k,
                               bool (*pick)(const ChartObservableResult&)) {
  std::vector<std::int8_t> out;
  for (const ChartVariantRow& row : table.variants) out.push_back(pick(row.observables[k]) ? 1 : 0);
  return out;
}

void write_h5(const std::string& path, const ChartSpec& chart, const ChartTable& table) {
  h5::File file = h5::File::create(path);
  file.set_attribute("carom_version", std::string(kVersion));
  file.set_attribute("chart_file", chart.file);
  file.set_attribute("scene", chart.scene);
  file.set_attribute("reference", chart.variants[chart.reference].name);
  std::vector<std::string> names, keys;
  for (const ChartVariant& v : chart.variants) names.push_back(v.name);
  for (const ChartObservable& o : chart.observables) keys.push_back(dataset_name(o.key));
  file.write_strings("observable_keys", keys);

  const h5::Group variants = file.create_group("variants");
  variants.write_strings("name", names);
  std::vector<std::int8_t> reference;
  std::vector<std::int64_t> n_cases, n_completed;
  std::vector<double> cost, cost_stderr;
  for (std::size_t v = 0; v < table.variants.size(); ++v) {
    const ChartVariantRow& row = table.variants[v];
    reference.push_back(v == chart.reference ? 1 : 0);
    n_cases.push_back(static_cast<std::int64_t>(row.cases));
    n_completed.push_back(static_cast<std::int64_t>(row.completed));
    cost.push_back(row.cost.mean);
    cost_stderr.push_back(row.cost.standard_error);
  }
  variants.write("reference", reference);
  variants.write("n_cases", n_cases);
  variants.write("n_completed", n_completed);
  variants.write("cost", cost);
  variants.write("cost_stderr", cost_stderr);

  const h5::Group observables = file.create_group("observables");
  for (std::size_t k = 0; k < chart.observables.size(); ++k) {
    const ChartObservable& o = chart.observables[k];
    const h5::Group g = observables.create_group(keys[k]);
    g.set_attribute("key", o.key);
    g.set_attribute("tolerance", o.tolerance);
    g.set_attribute("error_measure", std::string(measure_name(o.measure)));
    g.set_attribute("cheapest_within_tolerance",
                    static_cast<std::int64_t>(table.cheapest[k] ? *table.cheapest[k] : -1));
    std::vector<double> mean, stderr_, error, uncertainty, noise;
    for (const ChartVariantRow& row : table.variants) {
      const ChartObservableResult& r = row.observables[k];
      mean.push_back(r.statistics.mean);
      stderr_.push_back(r.statistics.standard_error);
      error.push_back(r.error.error);
      uncertainty.push_back(r.error.uncertainty);
      noise.push_back(r.error.noise);
    }
    g.write("mean", mean);
    g.write("stderr", stderr_);
    g.write("error", error);
    g.write("uncertainty", uncertainty);
    g.write("noise", noise);
    g.write("within_noise",
            flags(table, k, [](const ChartObservableResult& r) { return r.error.within_noise; }));
    g.write("within_tolerance",
            flags(table, k, [](const ChartObservableResult& r) { return r.within_tolerance; }));
    g.write("pareto",
            flags(table, k, [](const ChartObservableResult& r) { return r.front.on_front; }));
    g.write("pareto_within_noise", flags(table, k, [](const ChartObservableResult& r) {
              return r.front.dominated_within_noise;
            }));
  }

  const h5::Group cases = file.create_group("cases");
  std::vector<std::int64_t> index, variant;
  std::vector<std::uint64_t> seed;
  std::vector<std::string> status;
  std::vector<double> cpu, simulated, case_cost;
  for (const ChartCaseRow& c : table.cases) {
    index.push_back(static_cast<std::int64_t>(c.index));
    variant.push_back(static_cast<std::int64_t>(c.variant));
    seed.push_back(c.seed);
    status.push_back(c.status);
    cpu.push_back(c.cpu_seconds);
    simulated.push_back(c.simulated_seconds);
    case_cost.push_back(c.cost);
  }
  cases.write("case", index);
  cases.write("variant", variant);
  cases.write("seed", seed);
  cases.write_strings("status", status);
  cases.write("cpu_seconds", cpu);
  cases.write("simulated_seconds", simulated);
  cases.write("cost", case_cost);
  const h5::Group case_values = cases.create_group("observables");
  for (std::size_t k = 0; k < chart.observables.size(); ++k) {
    std::vector<double> column;
    for (const ChartCaseRow& c : table.cases) column.push_back(c.observables[k]);
    case_values.write(keys[k], column);
  }
  file.close();
}

/// "+1.2 % ± 0.4 %" or "+0.0123 ± 0.004".
std::string error_text(const ErrorEstimate& e, ErrorMeasure m) {
  if (std::isnan(e.error)) return "n/a";
  const double scale = m == ErrorMeasure::Relative ? 100 : 1;
  const std::string unit = m == ErrorMeasure::Relative ? " %" : "";
  std::string text = (e.error >= 0 ? "+" : "") + rounded(e.error * scale) + unit;
  if (!std::isnan(e.uncertainty)) text += " ± " + rounded(e.uncertainty * scale, 2) + unit;
  return text;
}

std::string cost_text(const SeedStatistics& s) {
  if (std::isnan(s.mean)) return "n/a";
  return rounded(s.mean) +
         (std::isnan(s.standard_error) ? "" : " ± " + rounded(s.standard_error, 2));
}

}  // namespace

std::string rounded(double x, int digits) {
  if (std::isnan(x)) return "";
  char text[32];
  std::snprintf(text, sizeof(text), "%.*g", digits, x);
  return text;
}

std::string chart_report(const ChartSpec& chart, const ChartTable& table) {
  std::ostringstream md;
  const std::string& reference = chart.variants[chart.reference].name;
  const ChartVariantRow& ref = table.variants[chart.reference];
  std::size_t completed = 0;
  for (const ChartCaseRow& c : table.cases) completed += c.status == "completed" ? 1 : 0;
  md << "# Chart " << fs::path(chart.file).filename().string() << "\n\n"
     << "Scene `" << chart.scene << "`, " << chart.variants.size() << " variants x "
     << chart.seeds.size() << " seeds (" << completed << " of " << table.cases.size()
     << " cases completed); reference: **" << reference << "**.\n\n"
     << "Cost: CPU seconds (user + system of each case's processes, setup and output "
        "included) per simulated second. Every value is the mean over the completed seeds ± "
        "its standard error; an error is against the reference's mean, ± the combined "
        "standard errors; *noise*: the error is smaller than that uncertainty.\n\n";
  if (completed < table.cases.size()) {
    md << "Not completed (left out of the statistics):\n\n";
    for (const ChartCaseRow& c : table.cases)
      if (c.status != "completed")
        md << "- case " << c.index << " (" << chart.variants[c.variant].name << ", seed " << c.seed
           << "): " << c.status << "\n";
    md << "\n";
  }

  md << "| variant | seeds | cost (CPU s / s) |";
  for (const ChartObservable& o : chart.observables)
    md << " `" << o.key << "` | error (" << measure_name(o.measure) << ") |";
  md << "\n|---|---|---|";
  for (std::size_t k = 0; k < chart.observables.size(); ++k) md << "---|---|";
  md << "\n";
  for (std::size_t v = 0; v < table.variants.size(); ++v) {
    const ChartVariantRow& row = table.variants[v];
    md << "| " << chart.variants[v].name << (v == chart.reference ? " (reference)" : "") << " | "
       << row.completed << " | " << cost_text(row.cost) << " |";
    for (std::size_t k = 0; k < chart.observables.size(); ++k) {
      const ChartObservableResult& r = row.observables[k];
      md << " " << cost_text(r.statistics) << " | "
         << (v == chart.reference ? std::string("—")
                                  : error_text(r.error, chart.observables[k].measure) +
                                        (r.error.within_noise ? " (noise)" : ""))
         << " |";
    }
    md << "\n";
  }

  for (std::size_t k = 0; k < chart.observables.size(); ++k) {
    const ChartObservable& o = chart.observables[k];
    const bool relative = o.measure == ErrorMeasure::Relative;
    md << "\n## `" << o.key << "`\n\n"
       << "Tolerance: "
       << (relative ? rounded(o.tolerance * 100) + " % (relative error)"
                    : rounded(o.tolerance) + " (absolute error)")
       << ".\n\n";
    if (!table.problems[k].empty()) {
      md << "Not compared: " << table.problems[k] << "\n";
      continue;
    }
    if (const auto best = table.cheapest[k]) {
      const ChartVariantRow& row = table.variants[*best];
      const ChartObservableResult& r = row.observables[k];
      md << "Cheapest within the tolerance: **" << chart.variants[*best].name << "**, "
         << rounded(row.cost.mean) << " CPU s per simulated s, error "
         << error_text(r.error, o.measure) << (r.error.within_noise ? " (within noise)" : "");
      if (!std::isnan(ref.cost.mean) && row.cost.mean > 0) {
        const double ratio = ref.cost.mean / row.cost.mean;
        if (ratio >= 1)
          md << "; " << rounded(ratio, 2) << " times cheaper than the reference ("
             << rounded(ref.cost.mean) << ")";
        else
          md << "; " << rounded(1 / ratio, 2) << " times the reference's cost ("
             << rounded(ref.cost.mean) << ")";
      }
      md << ".";
      if (ref.cost.mean < row.cost.mean)
        md << " The reference itself is cheaper than every variant within the tolerance.";
      if (std::isfinite(r.error.uncertainty) && r.error.uncertainty > o.tolerance)
        md << " Its uncertainty exceeds the tolerance: more seeds would be needed to be sure.";
      md << "\n";
    } else {
      md << "**No variant** other than the reference is within the tolerance.\n";
    }
    std::vector<std::size_t> by_cost(table.variants.size());
    for (std::size_t v = 0; v < by_cost.size(); ++v) by_cost[v] = v;
    std::stable_sort(by_cost.begin(), by_cost.end(), [&](std::size_t a, std::size_t b) {
      return table.variants[a].cost.mean < table.variants[b].cost.mean;
    });
    std::string front, noisy;
    for (const std::size_t v : by_cost) {
      const FrontMembership& f = table.variants[v].observables[k].front;
      if (f.on_front) front += (front.empty() ? "" : ", ") + chart.variants[v].name;
      if (f.dominated_within_noise) noisy += (noisy.empty() ? "" : ", ") + chart.variants[v].name;
    }
    md << "\nPareto front (cheapest to most accurate): " << (front.empty() ? "none" : front) << ".";
    if (!noisy.empty()) md << " Dominated only within noise: " << noisy << ".";
    md << "\n\nFigure: `pareto_" << dataset_name(o.key) << ".png` (`/usr/bin/python3 "
       << "scenarios/plots/chart_plot.py " << chart.out << "`).\n";
  }
  return md.str();
}

void write_chart(const ChartSpec& chart, const ChartTable& table) {
  const fs::path out = chart.out;
  write_text_atomically((out / "chart.csv").string(), variants_csv(chart, table));
  write_text_atomically((out / "chart_cases.csv").string(), cases_csv(chart, table));
  const std::string h5_path = (out / "chart.h5").string();
  write_h5(h5_path + ".tmp", chart, table);
  fs::rename(h5_path + ".tmp", h5_path);
  write_text_atomically((out / "report.md").string(), chart_report(chart, table));
}

}  // namespace carom
