#include "scenarios/sweep/sweep_case.hpp"

#include <cstdio>
#include <deque>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "scenarios/scene/scene_reader.hpp"
#include "scenarios/run/summary.hpp"

namespace carom {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

namespace {

/// The JSON document in `path`, or a null one when it is missing or unreadable.
Json read_json(const fs::path& path) {
  std::ifstream in(path);
  if (!in) return Json();
  try {
    return Json::parse(in);
  } catch (const Json::exception&) {
    return Json();
  }
}

/// summary.json's status, "" when there is none.
std::string summary_status(const std::string& dir) {
  const Json summary = read_json(fs::path(dir) / "summary.json");
  if (summary.is_object() && summary.contains("status") && summary["status"].is_string())
    return summary["status"].get<std::string>();
  return "";
}

std::string describe_case(const std::vector<std::string>& overrides, std::uint64_t seed) {
  std::string text;
  for (const std::string& o : overrides) text += "--set " + o + " ";
  return text + "--seed " + std::to_string(seed);
}

}  // namespace

std::string case_directory(const std::string& out, std::size_t index) {
  char name[32];
  std::snprintf(name, sizeof(name), "%04zu", index);
  return (fs::path(out) / "cases" / name).string();
}

std::string scene_digest(const std::string& scene_text) {
  const std::size_t first_line = scene_text.find('\n');
  std::uint64_t hash = 0xcbf29ce484222325ull;  // FNV-1a, 64 bits
  for (std::size_t k = first_line == std::string::npos ? 0 : first_line + 1; k < scene_text.size();
       ++k) {
    hash ^= static_cast<unsigned char>(scene_text[k]);
    hash *= 0x100000001b3ull;
  }
  char text[20];
  std::snprintf(text, sizeof(text), "%016llx", static_cast<unsigned long long>(hash));
  return text;
}

void check_case_record(const std::string& dir, const SweepCase& c, const std::string& digest,
                       const std::string& out) {
  const fs::path path = fs::path(dir) / "case.json";
  if (!fs::exists(path)) return;
  const Json record = read_json(path);
  const std::string advice =
      "; the sweep file (or its scene) changed since. Give the changed sweep another `out`, "
      "or remove " +
      out + " to start over.";
  if (!record.is_object() || !record.contains("overrides") || !record.contains("seed") ||
      !record.contains("scene_digest"))
    throw SceneError(path.string() + " is not a case record of carom sweep" + advice);
  const auto overrides = record["overrides"].get<std::vector<std::string>>();
  const auto seed = record["seed"].get<std::uint64_t>();
  if (overrides != c.overrides || seed != c.seed)
    throw SceneError("case " + std::to_string(c.index) + " in " + dir + " was run with " +
                     describe_case(overrides, seed) + ", but the sweep file now makes it " +
                     describe_case(c.overrides, c.seed) + advice);
  if (record["scene_digest"].get<std::string>() != digest)
    throw SceneError("case " + std::to_string(c.index) + " in " + dir +
                     " was run with a different scene (" + record.value("scene", std::string("?")) +
                     " has changed in more than comments)" + advice);
}

void write_case_record(const std::string& dir, const SweepCase& c, const std::string& digest,
                       const std::string& scene) {
  const fs::path path = fs::path(dir) / "case.json";
  if (fs::exists(path)) return;
  fs::create_directories(dir);
  Json record;
  record["case"] = c.index;
  record["group"] = c.group;
  record["scene"] = scene;
  record["overrides"] = c.overrides;
  record["seed"] = c.seed;
  record["scene_digest"] = digest;
  write_text_atomically(path.string(), record.dump(2) + "\n");
}

CaseResult read_case_result(const std::string& dir) {
  CaseResult result;
  const Json record = read_json(fs::path(dir) / "result.json");
  if (record.is_object()) {
    result.status = record.value("status", result.status);
    result.exit_code = record.value("exit_code", result.exit_code);
    result.elapsed_seconds = record.value("elapsed_seconds", 0.0);
    result.cpu_seconds = record.value("cpu_seconds", 0.0);
    result.attempts = record.value("attempts", 0);
    result.rank = record.value("rank", 0);
    result.message = record.value("message", std::string());
    result.log_tail = record.value("log_tail", std::string());
  }
  const std::string summary = summary_status(dir);
  if (summary == "completed") {
    result.status = "completed";
    result.exit_code = 0;
    result.message.clear();
  } else if (!record.is_object() &&
             (summary == "interrupted" || fs::exists(fs::path(dir) / "checkpoint.h5"))) {
    result.status = "interrupted";  // a sweep was killed before it could record the case
  }
  return result;
}

void write_case_result(const std::string& dir, const CaseResult& result) {
  Json record;
  record["status"] = result.status;
  record["exit_code"] = result.exit_code;
  record["elapsed_seconds"] = result.elapsed_seconds;
  record["cpu_seconds"] = result.cpu_seconds;
  record["attempts"] = result.attempts;
  record["rank"] = result.rank;
  record["message"] = result.message;
  record["log_tail"] = result.log_tail;
  write_text_atomically((fs::path(dir) / "result.json").string(), record.dump(2) + "\n");
}

CaseAction next_action(const std::string& dir, bool retry_failed) {
  const CaseResult result = read_case_result(dir);
  if (result.status == "completed") return CaseAction::Skip;
  if (result.status == "interrupted")
    return fs::exists(fs::path(dir) / "checkpoint.h5") ? CaseAction::Resume : CaseAction::Run;
  if (result.status == "not_run") return CaseAction::Run;
  return retry_failed ? CaseAction::Run : CaseAction::Skip;
}

CaseResult attempt_result(const std::string& dir, const CaseResult& previous, int exit_code,
                          int signal, bool asked_to_stop, double wall_seconds, int rank,
                          double cpu_seconds) {
  CaseResult result = previous;
  result.attempts += 1;
  result.elapsed_seconds += wall_seconds;
  result.cpu_seconds += cpu_seconds;
  result.rank = rank;
  result.exit_code = exit_code;
  result.message.clear();
  result.log_tail.clear();
  const std::string summary = summary_status(dir);
  if (exit_code == 0 && summary == "completed") {
    result.status = "completed";
    return result;
  }
  if (exit_code == 130 || (signal != 0 && asked_to_stop)) {
    result.status = "interrupted";
    result.message = "interrupted; the next `carom sweep` continues it";
    return result;
  }
  const std::string log = (fs::path(dir) / "log.txt").string();
  result.log_tail = tail_of_file(log, 10);
  const std::string last_line = tail_of_file(log, 1);
  if (signal != 0) {
    result.status = "killed";
    result.message = "killed by signal " + std::to_string(signal) +
                     (signal == 9 ? " (SIGKILL: out of memory?)" : "");
  } else if (exit_code == 0) {
    result.status = "failed";
    result.message = "exited 0 but its summary.json does not say completed";
  } else if (exit_code == 2) {
    result.status = "bad_scene";
  } else if (exit_code == 1 && !summary.empty() && summary != "completed" &&
             summary != "interrupted") {
    result.status = summary;  // inelastic_collapse, kick_unstable, ...
  } else {
    result.status = "failed";
  }
  if (result.message.empty())
    result.message = last_line.empty() ? "exit code " + std::to_string(exit_code) : last_line;
  return result;
}

std::string tail_of_file(const std::string& path, std::size_t lines) {
  std::ifstream in(path);
  std::deque<std::string> kept;
  std::string line;
  while (std::getline(in, line)) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    kept.push_back(line);
    if (kept.size() > lines) kept.pop_front();
  }
  std::string text;
  for (const std::string& l : kept) text += (text.empty() ? "" : "\n") + l;
  return text;
}

}  // namespace carom
