// `carom info FILE.h5`: a run file, checkpoint or sweep summary described in a few lines.
#include "scenarios/cli/info.hpp"

#include <hdf5.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <toml++/toml.h>
#include <vector>

#include "core/display_number.hpp"
#include "core/hdf5.hpp"
#include "scenarios/run/output_estimate.hpp"
#include "scenarios/scene/scene_reader.hpp"

namespace carom {

namespace fs = std::filesystem;
using InfoJson = nlohmann::json;

namespace {

/// A root attribute as text ("" when absent).
std::string text_attribute(const h5::Object& object, const std::string& name) {
  if (!object.has_attribute(name)) return "";
  try {
    return object.attribute<std::string>(name);
  } catch (const std::exception&) {
    return display_number(object.attribute<double>(name));
  }
}

/// "3 large, 2407 fines" from species names and counts (counts by species index).
std::string species_text(const std::vector<std::string>& names, const std::vector<double>& diameters,
                         const std::vector<std::uint64_t>& counts) {
  std::string text;
  for (std::size_t s = 0; s < names.size(); ++s) {
    text += (s ? "; " : "") + names[s] + ": " + std::to_string(s < counts.size() ? counts[s] : 0) + " particles";
    if (s < diameters.size()) text += " of d = " + display_number(diameters[s]) + " m";
  }
  return text;
}

/// summary.json beside the file, or null.
InfoJson read_summary(const std::string& path) {
  const fs::path summary = fs::path(path).parent_path() / "summary.json";
  std::ifstream in(summary);
  if (!in) return InfoJson();
  try {
    return InfoJson::parse(in);
  } catch (const InfoJson::exception&) {
    return InfoJson();
  }
}

/// The number at `key` of a JSON object, NaN when absent or not a number.
double number_at(const InfoJson& object, const char* key) {
  return object.is_object() && object.contains(key) && object[key].is_number() ? object[key].get<double>() : NAN;
}

/// The headline numbers of summary.json.
void print_summary(const InfoJson& summary, std::ostream& out) {
  out << "status (summary.json): " << summary.value("status", std::string("?"));
  const std::string message = summary.value("message", std::string());
  if (!message.empty()) out << ": " << message;
  out << "\n";
  out << "  simulated t = " << display_number(number_at(summary, "start_time")) << " to "
      << display_number(number_at(summary, "end_time")) << " s in " << display_number(number_at(summary, "wall_seconds"))
      << " s of wall time; " << display_number(number_at(summary, "events_total")) << " events, "
      << display_number(number_at(summary, "collisions_total")) << " collisions ("
      << display_number(number_at(summary, "collisions_per_second")) << " per wall second)\n";
  if (summary.contains("collision_rate_per_particle") && summary["collision_rate_per_particle"].is_object()) {
    out << "  collision rate per particle (1/s):";
    for (const auto& [pair, rate] : summary["collision_rate_per_particle"].items())
      out << " " << pair << " " << (rate.is_number() ? display_number(rate.get<double>()) : std::string("n/a"));
    out << "\n";
  }
  if (!summary.contains("analysis") || !summary["analysis"].is_object()) return;
  const InfoJson& analysis = summary["analysis"];
  if (analysis.contains("mixing")) {
    const InfoJson& m = analysis["mixing"];
    out << "  mixing of " << m.value("species", std::string("?")) << ": Lacey index "
        << display_number(number_at(m, "lacey_start")) << " -> " << display_number(number_at(m, "lacey_end"))
        << ", rate k = " << display_number(number_at(m, "rate")) << " 1/s\n";
  }
  if (analysis.contains("segregation_index")) {
    const InfoJson& s = analysis["segregation_index"];
    out << "  segregation index " << display_number(number_at(s, "start")) << " -> " << display_number(number_at(s, "end"))
        << "\n";
  }
}

void print_run(const h5::File& file, const std::string& path, std::ostream& out) {
  const h5::Group species = file.open_group("species");
  const std::vector<std::string> names = species.read_strings("name");
  out << "species: "
      << species_text(names, species.read<double>("diameter"), species.read<std::uint64_t>("count")) << "\n";
  const h5::Group snapshots = file.open_group("snapshots");
  const std::vector<std::string> children = snapshots.children();
  out << "snapshots: " << children.size();
  if (!children.empty())
    out << ", t = " << display_number(snapshots.open_group(children.front()).attribute<double>("time")) << " to "
        << display_number(snapshots.open_group(children.back()).attribute<double>("time")) << " s";
  out << "\n";
  const h5::Group series = file.open_group("timeseries");
  const std::vector<double> times = series.read<double>("time");
  out << "time series: " << times.size() << " rows";
  if (!times.empty()) out << ", t = " << display_number(times.front()) << " to " << display_number(times.back()) << " s";
  out << " (" << series.children().size() << " series)\n";
  if (!times.empty()) {
    const std::vector<double> total = series.read<double>("total_energy");
    const std::vector<double> dissipated = series.read<double>("dissipated");
    if (!total.empty() && !dissipated.empty())
      out << "  at the last row: total energy " << display_number(total.back()) << " J, dissipated "
          << display_number(dissipated.back()) << " J\n";
  }
  if (file.contains("gas")) {
    const h5::Group gas = file.open_group("gas");
    const std::vector<std::int32_t> cells = gas.read<std::int32_t>("cells", {3});
    out << "gas: " << cells[0] << " x " << cells[1] << " x " << cells[2] << " cells, closure "
        << gas.read_string("closure") << "\n";
  }
  const InfoJson summary = read_summary(path);
  if (summary.is_object()) {
    print_summary(summary, out);
    return;
  }
  out << "status: no summary.json beside the file (the run is still going, or was killed)";
  // How far: the last row against the scene's time.end (carom resume --end may move it).
  double end = NAN;
  try {
    const toml::table scene = toml::parse(file.read_string("scene"));
    end = scene["time"]["end"].value<double>().value_or(NAN);
  } catch (const std::exception&) {
  }
  if (!times.empty() && end > 0)
    out << "; t = " << display_number(times.back()) << " s of time.end = " << display_number(end) << " s ("
        << display_number(std::round(1000.0 * times.back() / end) / 10.0) << " %) at the last flush";
  out << "\n";
}

void print_checkpoint(const h5::File& file, std::ostream& out) {
  const h5::Group state = file.open_group("state");
  out << "state of method " << text_attribute(state, "method") << " at t = " << display_number(state.attribute<double>("time"))
      << " s";
  if (state.contains("particles")) {
    const std::vector<std::uint32_t> species = state.open_group("particles").read<std::uint32_t>("species");
    std::map<std::uint32_t, std::size_t> count;
    for (std::uint32_t s : species) ++count[s];
    out << ", " << species.size() << " particles (by species index:";
    for (const auto& [s, n] : count) out << " " << s << ": " << n;
    out << ")";
  }
  out << (file.contains("gas") ? "; with the gas's state" : "") << "\n";
  out << "continue it with: carom resume " << "DIR (the directory that holds it)\n";
}

void print_sweep(const h5::File& file, std::ostream& out) {
  out << "sweep file " << text_attribute(file, "sweep_file") << " over scene " << text_attribute(file, "scene") << "\n";
  if (!file.contains("cases")) return;
  const std::vector<std::string> status = file.open_group("cases").read_strings("status");
  std::map<std::string, std::size_t> tally;
  for (const std::string& s : status) ++tally[s];
  out << status.size() << " cases:";
  for (const auto& [s, n] : tally) out << " " << n << " " << s << ";";
  out << "\n";
}

}  // namespace

void require_hdf5_file(const std::string& path) {
  std::error_code error;
  if (!fs::exists(path, error)) throw SceneError(path + ": no such file");
  if (fs::is_directory(path, error))
    throw SceneError(path + ": is a directory; carom info reads one file (e.g. " + (fs::path(path) / "run.h5").string() +
                     ")");
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  if (H5Fis_hdf5(path.c_str()) <= 0)
    throw SceneError(path + ": not an HDF5 file (carom info reads a run.h5, checkpoint.h5 or a sweep's summary.h5)");
}

void print_file_info(const std::string& path, std::ostream& out) {
  require_hdf5_file(path);
  // Unlocked: a run still being written is read as of its last flush (each snapshot).
  const h5::File file = h5::File::open_unlocked(path);
  const std::string kind = text_attribute(file, "kind");
  const bool sweep = kind.empty() && file.has_attribute("sweep_file");
  if (kind != "carom run" && kind != "carom checkpoint" && !sweep)
    throw SceneError(path + ": an HDF5 file, but not a carom run file, checkpoint or sweep summary (root attribute "
                     "'kind' is " + (kind.empty() ? std::string("missing") : "\"" + kind + "\"") +
                     "); `carom info --tree " + path + "` lists what it holds");
  out << path << ": " << (sweep ? std::string("carom sweep summary") : kind + " file") << ", "
      << byte_text(static_cast<double>(fs::file_size(path))) << "\n";
  if (!sweep)
    out << "scene \"" << text_attribute(file, "scene_name") << "\", carom " << text_attribute(file, "carom_version")
        << ", seed " << (file.has_attribute("seed") ? std::to_string(file.attribute<std::uint64_t>("seed")) : "?")
        << "\n";
  if (sweep)
    print_sweep(file, out);
  else if (kind == "carom run")
    print_run(file, path, out);
  else
    print_checkpoint(file, out);
  out << "(carom info --tree " << path << " lists every group and dataset)\n";
}

}  // namespace carom
