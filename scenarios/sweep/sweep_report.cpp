#include "scenarios/sweep/sweep_report.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "carom/version.hpp"
#include "core/hdf5.hpp"
#include "scenarios/scene/scene_reader.hpp"
#include "scenarios/run/summary.hpp"

namespace carom {

namespace fs = std::filesystem;

namespace {

std::string number_cell(double x) {
  return std::isnan(x) ? std::string() : format_number(x);
}

/// A dataset name for a column ('/' would make a path).
std::string cases_csv(const SweepSpec& spec, const SweepTable& table) {
  std::ostringstream csv;
  csv << "case,group";
  for (const SweepAxis& axis : spec.axes) csv << "," << csv_cell(axis.key);
  csv << ",seed,status,exit_code,elapsed_seconds,attempts";
  for (const std::string& metric : table.metrics) csv << "," << csv_cell(metric);
  csv << ",message\n";
  for (const CaseRow& row : table.cases) {
    csv << row.c.index << "," << row.c.group;
    for (std::size_t a = 0; a < spec.axes.size(); ++a)
      csv << "," << csv_cell(spec.axes[a].values[row.c.choice[a]].label);
    csv << "," << row.c.seed << "," << row.result.status << "," << row.result.exit_code << ","
        << number_cell(row.result.elapsed_seconds) << "," << row.result.attempts;
    for (const double x : row.metrics) csv << "," << number_cell(x);
    csv << "," << csv_cell(row.result.message) << "\n";
  }
  return csv.str();
}

std::string groups_csv(const SweepSpec& spec, const SweepTable& table,
                       const std::vector<SweepCase>& first_cases) {
  std::ostringstream csv;
  csv << "group";
  for (const SweepAxis& axis : spec.axes) csv << "," << csv_cell(axis.key);
  csv << ",n_cases,n_completed";
  for (const std::string& metric : table.metrics)
    csv << "," << csv_cell(metric + ":mean") << "," << csv_cell(metric + ":std");
  csv << "\n";
  for (const GroupRow& group : table.groups) {
    csv << group.group;
    for (std::size_t a = 0; a < spec.axes.size(); ++a)
      csv << "," << csv_cell(spec.axes[a].values[first_cases[group.group].choice[a]].label);
    csv << "," << group.cases << "," << group.completed;
    for (std::size_t m = 0; m < table.metrics.size(); ++m)
      csv << "," << number_cell(group.mean[m]) << "," << number_cell(group.stddev[m]);
    csv << "\n";
  }
  return csv.str();
}

/// A varied key's values along rows (numbers when the axis is numeric, else labels).
void write_axis(const h5::Group& group, const SweepAxis& axis,
                const std::vector<std::size_t>& choices) {
  if (axis.numeric()) {
    std::vector<double> values;
    for (const std::size_t k : choices) values.push_back(*axis.values[k].number);
    group.write(dataset_name(axis.key), values);
  } else {
    std::vector<std::string> labels;
    for (const std::size_t k : choices) labels.push_back(axis.values[k].label);
    group.write_strings(dataset_name(axis.key), labels);
  }
}

void write_h5(const std::string& path, const SweepSpec& spec, const SweepTable& table,
              const std::vector<SweepCase>& first_cases) {
  h5::File file = h5::File::create(path);
  file.set_attribute("carom_version", std::string(kVersion));
  file.set_attribute("sweep_file", spec.file);
  file.set_attribute("scene", spec.scene);
  std::vector<std::string> keys, metrics;
  for (const SweepAxis& axis : spec.axes) keys.push_back(dataset_name(axis.key));
  for (const std::string& metric : table.metrics) metrics.push_back(dataset_name(metric));
  file.write_strings("varied_keys", keys);
  file.write_strings("metrics", metrics);

  const h5::Group cases = file.create_group("cases");
  std::vector<std::int64_t> index, group, exit_code, attempts;
  std::vector<std::uint64_t> seed;
  std::vector<double> elapsed;
  std::vector<std::string> status, message;
  for (const CaseRow& row : table.cases) {
    index.push_back(static_cast<std::int64_t>(row.c.index));
    group.push_back(static_cast<std::int64_t>(row.c.group));
    seed.push_back(row.c.seed);
    status.push_back(row.result.status);
    exit_code.push_back(row.result.exit_code);
    elapsed.push_back(row.result.elapsed_seconds);
    attempts.push_back(row.result.attempts);
    message.push_back(row.result.message);
  }
  cases.write("case", index);
  cases.write("group", group);
  cases.write("seed", seed);
  cases.write_strings("status", status);
  cases.write("exit_code", exit_code);
  cases.write("elapsed_seconds", elapsed);
  cases.write("attempts", attempts);
  cases.write_strings("message", message);
  for (std::size_t a = 0; a < spec.axes.size(); ++a) {
    std::vector<std::size_t> choices;
    for (const CaseRow& row : table.cases) choices.push_back(row.c.choice[a]);
    write_axis(cases, spec.axes[a], choices);
  }
  for (std::size_t m = 0; m < table.metrics.size(); ++m) {
    std::vector<double> column;
    for (const CaseRow& row : table.cases) column.push_back(row.metrics[m]);
    cases.write(metrics[m], column);
  }

  const h5::Group groups = file.create_group("groups");
  std::vector<std::int64_t> group_index, n_cases, n_completed;
  for (const GroupRow& g : table.groups) {
    group_index.push_back(static_cast<std::int64_t>(g.group));
    n_cases.push_back(static_cast<std::int64_t>(g.cases));
    n_completed.push_back(static_cast<std::int64_t>(g.completed));
  }
  groups.write("group", group_index);
  groups.write("n_cases", n_cases);
  groups.write("n_completed", n_completed);
  for (std::size_t a = 0; a < spec.axes.size(); ++a) {
    std::vector<std::size_t> choices;
    for (const GroupRow& g : table.groups) choices.push_back(first_cases[g.group].choice[a]);
    write_axis(groups, spec.axes[a], choices);
  }
  const h5::Group mean = groups.create_group("mean");
  const h5::Group stddev = groups.create_group("std");
  for (std::size_t m = 0; m < table.metrics.size(); ++m) {
    std::vector<double> means, stds;
    for (const GroupRow& g : table.groups) {
      means.push_back(g.mean[m]);
      stds.push_back(g.stddev[m]);
    }
    mean.write(metrics[m], means);
    stddev.write(metrics[m], stds);
  }
  file.close();
}

}  // namespace

std::string dataset_name(std::string key) {
  std::replace(key.begin(), key.end(), '/', '_');
  return key;
}

std::string csv_cell(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

void write_sweep_summary(const SweepSpec& spec, const SweepTable& table) {
  // The choices of each group, from its first case (every case of a group has the same ones).
  std::vector<SweepCase> first_cases(table.groups.size());
  for (auto it = table.cases.rbegin(); it != table.cases.rend(); ++it)
    first_cases[it->c.group] = it->c;
  const fs::path out = spec.out;
  write_text_atomically((out / "summary.csv").string(), cases_csv(spec, table));
  write_text_atomically((out / "summary_by_group.csv").string(),
                        groups_csv(spec, table, first_cases));
  const std::string h5_path = (out / "summary.h5").string();
  write_h5(h5_path + ".tmp", spec, table, first_cases);
  fs::rename(h5_path + ".tmp", h5_path);
}

}  // namespace carom
