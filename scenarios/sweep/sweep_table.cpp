#include "scenarios/sweep/sweep_table.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

namespace carom {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

namespace {

void collect(const Json& node, const std::string& path,
             std::vector<std::pair<std::string, double>>& out) {
  if (node.is_number()) {
    out.emplace_back(path, node.get<double>());
  } else if (node.is_object()) {
    for (const auto& [key, value] : node.items())
      collect(value, path.empty() ? key : path + "." + key, out);
  } else if (node.is_array()) {
    for (std::size_t k = 0; k < node.size(); ++k)
      collect(node[k], path + "." + std::to_string(k), out);
  }
}

}  // namespace

std::vector<std::pair<std::string, double>> numeric_leaves(const std::string& json_text) {
  std::vector<std::pair<std::string, double>> out;
  try {
    collect(Json::parse(json_text), "", out);
  } catch (const Json::exception&) {
    // An unreadable summary (a run killed while writing it) has no metrics.
  }
  return out;
}

std::vector<std::string> fixed_case_columns(const SweepSpec& spec) {
  std::vector<std::string> columns{"case", "group"};
  for (const SweepAxis& axis : spec.axes) columns.push_back(axis.key);
  for (const char* name : {"seed", "status", "exit_code", "elapsed_seconds", "attempts", "message"})
    columns.emplace_back(name);
  return columns;
}

SweepTable gather_sweep(const SweepSpec& spec, const std::vector<SweepCase>& cases) {
  SweepTable table;
  const std::vector<std::string> fixed = fixed_case_columns(spec);
  std::map<std::string, std::size_t> column_of;
  std::vector<std::vector<std::pair<std::size_t, double>>> values(cases.size());
  for (const SweepCase& c : cases) {
    const std::string dir = case_directory(spec.out, c.index);
    std::ifstream in(fs::path(dir) / "summary.json");
    std::stringstream text;
    if (in) text << in.rdbuf();
    for (auto& [name, value] : numeric_leaves(text.str())) {
      const std::string column =
          std::find(fixed.begin(), fixed.end(), name) != fixed.end() ? "summary." + name : name;
      auto [where, added] = column_of.emplace(column, table.metrics.size());
      if (added) table.metrics.push_back(column);
      values[c.index].emplace_back(where->second, value);
    }
  }
  for (const SweepCase& c : cases) {
    CaseRow row{c, read_case_result(case_directory(spec.out, c.index)),
                std::vector<double>(table.metrics.size(), kMissing)};
    for (const auto& [column, value] : values[c.index]) row.metrics[column] = value;
    table.cases.push_back(std::move(row));
  }

  table.groups.resize(spec.group_count());
  for (std::size_t g = 0; g < table.groups.size(); ++g) table.groups[g].group = g;
  const std::size_t M = table.metrics.size();
  std::vector<std::vector<std::vector<double>>> samples(table.groups.size(),
                                                        std::vector<std::vector<double>>(M));
  for (const CaseRow& row : table.cases) {
    GroupRow& group = table.groups[row.c.group];
    ++group.cases;
    if (row.result.status != "completed") continue;
    ++group.completed;
    for (std::size_t m = 0; m < M; ++m)
      if (!std::isnan(row.metrics[m])) samples[row.c.group][m].push_back(row.metrics[m]);
  }
  for (GroupRow& group : table.groups) {
    group.mean.assign(M, kMissing);
    group.stddev.assign(M, kMissing);
    for (std::size_t m = 0; m < M; ++m) {
      const std::vector<double>& x = samples[group.group][m];
      if (x.empty()) continue;
      double sum = 0;
      for (const double v : x) sum += v;
      const double mean = sum / static_cast<double>(x.size());
      group.mean[m] = mean;
      if (x.size() < 2) continue;
      double squares = 0;
      for (const double v : x) squares += (v - mean) * (v - mean);
      group.stddev[m] = std::sqrt(squares / static_cast<double>(x.size() - 1));
    }
  }
  return table;
}

}  // namespace carom
