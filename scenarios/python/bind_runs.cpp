// carom.run, resume, sweep and chart: the commands' own functions (run_scene, resume_run,
// run_sweep, run_chart), called as `carom` calls them. Each returns the command's exit code and
// what it wrote to stderr; the package's __init__.py turns those into results and exceptions.
#include <pybind11/stl.h>

#include <iostream>
#include <optional>
#include <sstream>
#include <streambuf>

#include "scenarios/chart/chart.hpp"
#include "scenarios/python/bindings.hpp"
#include "scenarios/python/scene_source.hpp"
#include "scenarios/python/signal_guard.hpp"
#include "scenarios/run/run.hpp"
#include "scenarios/sweep/sweep.hpp"
#include "scenarios/sweep/sweep_pool.hpp"

namespace py = pybind11;

namespace carom::python {

namespace {

/// While alive, what is written to std::cerr still goes there and is also kept, so that an
/// exception raised from an exit code can carry the command's own message.
class KeptErrors : public std::streambuf {
 public:
  KeptErrors() : original_(std::cerr.rdbuf(this)) {}
  ~KeptErrors() override { std::cerr.rdbuf(original_); }
  KeptErrors(const KeptErrors&) = delete;
  KeptErrors& operator=(const KeptErrors&) = delete;
  const std::string& text() const { return kept_; }

 protected:
  int_type overflow(int_type c) override {
    if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
    kept_.push_back(traits_type::to_char_type(c));
    return original_->sputc(traits_type::to_char_type(c));
  }
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    kept_.append(s, static_cast<std::size_t>(n));
    return original_->sputn(s, n);
  }
  int sync() override { return original_->pubsync(); }

 private:
  std::streambuf* original_;
  std::string kept_;
};

/// Runs `command` with Python's lock released, carom's signal handlers installed and stderr
/// kept; returns (exit code, stderr).
template <typename Command>
std::pair<int, std::string> call(Command command) {
  const py::gil_scoped_release unlocked;
  const SignalGuard signals;
  KeptErrors errors;
  const int code = command();
  return {code, errors.text()};
}

/// The options of `carom sweep` or `carom chart` (SweepOptions, ChartOptions: the same fields),
/// with their cases run by the `carom` binary, not by Python.
template <class Options>
Options pool_options(const std::string& file, std::optional<std::string> out, std::size_t jobs, bool retry_failed,
                     bool dry_run, bool quiet) {
  Options options;
  options.file = file;
  options.out = std::move(out);
  options.jobs = jobs;
  options.retry_failed = retry_failed;
  options.dry_run = dry_run;
  options.quiet = quiet;
  set_case_executable(CAROM_EXECUTABLE);
  return options;
}

}  // namespace

void bind_runs(py::module_& m) {
  m.def(
      "_run",
      [](const SceneSource& source, const std::string& out, bool quiet, bool overwrite) {
        RunOptions options;
        options.out_dir = out;
        options.quiet = quiet;
        options.overwrite = overwrite;
        Scene scene = source.scene();
        return call([&] { return run_scene(std::move(scene), options); });
      },
      py::arg("scene"), py::arg("out"), py::arg("quiet"), py::arg("overwrite"),
      "`carom run`: (exit code, stderr).");
  m.def(
      "_resume",
      [](const std::string& dir, std::optional<double> end, bool quiet) {
        return call([&] { return resume_run(dir, end, quiet); });
      },
      py::arg("dir"), py::arg("end"), py::arg("quiet"), "`carom resume`: (exit code, stderr).");
  m.def(
      "_sweep",
      [](const std::string& file, std::optional<std::string> out, std::size_t jobs, bool retry_failed, bool dry_run,
         bool quiet) {
        const auto options = pool_options<SweepOptions>(file, std::move(out), jobs, retry_failed, dry_run, quiet);
        return call([&] { return run_sweep(options); });
      },
      py::arg("file"), py::arg("out"), py::arg("jobs"), py::arg("retry_failed"), py::arg("dry_run"),
      py::arg("quiet"), "`carom sweep`: (exit code, stderr).");
  m.def(
      "_chart",
      [](const std::string& file, std::optional<std::string> out, std::size_t jobs, bool retry_failed, bool dry_run,
         bool quiet) {
        const auto options = pool_options<ChartOptions>(file, std::move(out), jobs, retry_failed, dry_run, quiet);
        return call([&] { return run_chart(options); });
      },
      py::arg("file"), py::arg("out"), py::arg("jobs"), py::arg("retry_failed"), py::arg("dry_run"),
      py::arg("quiet"), "`carom chart`: (exit code, stderr).");
}

}  // namespace carom::python
