#include "scenarios/sweep/sweep_pool.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string_view>
#include <utility>

#include "core/worker_pool.hpp"

extern char** environ;

namespace carom {

bool follow_sweep_parent() {
  const char* text = std::getenv(kSweepParentVariable);
  if (text == nullptr) return true;
  const long parent = std::strtol(text, nullptr, 10);
  prctl(PR_SET_PDEATHSIG, SIGTERM);
  // The sweep may have ended before the line above: then the parent is already another process.
  return parent <= 0 || getppid() == static_cast<pid_t>(parent);
}

namespace {

/// Stop signals received so far, and the last one (handlers only write these).
volatile sig_atomic_t g_signals = 0;
volatile sig_atomic_t g_last_signal = SIGINT;

extern "C" void on_sweep_signal(int signal) {
  g_last_signal = signal;
  g_signals = g_signals + 1;
}

/// The binary the cases run, when not this one (set_case_executable).
std::string g_case_executable;

/// The running binary, so children are the same carom whatever PATH says.
std::string own_executable() {
  if (!g_case_executable.empty()) return g_case_executable;
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error)
    throw std::runtime_error("cannot find this program's path (/proc/self/exe): " +
                             error.message());
  return self.string();
}

}  // namespace

void set_case_executable(std::string path) { g_case_executable = std::move(path); }

void install_sweep_signal_handlers() {
  g_signals = 0;  // a process that sweeps again (the Python module) starts with no stop asked
  struct sigaction action {};
  action.sa_handler = on_sweep_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

bool sweep_stop_requested() {
  return g_signals > 0;
}

const volatile std::sig_atomic_t* sweep_stop_flag() {
  return &g_signals;
}

ProcessPool::ProcessPool(std::size_t slots)
    : slots_(slots < 1 ? 1 : slots), executable_(own_executable()) {
  // Cases running side by side share the cores: each gets its part of the threads (a relax
  // run uses every core it may run on by default), unless the user chose.
  if (std::getenv("CAROM_THREADS") == nullptr) {
    const auto hardware = static_cast<std::size_t>(WorkerPool::default_threads());
    const std::string per_case = std::to_string(std::max<std::size_t>(1, hardware / slots_));
    setenv("CAROM_THREADS", per_case.c_str(), 1);
  }
}

ProcessPool::~ProcessPool() {
  for (const Child& child : running_) kill(child.pid, SIGTERM);
  for (const Child& child : running_) {
    int status = 0;
    while (waitpid(child.pid, &status, 0) < 0 && errno == EINTR) {
    }
  }
}

void ProcessPool::start(std::size_t tag, const std::vector<std::string>& args,
                        const std::string& log_path) {
  std::vector<std::string> argv_text{executable_};
  argv_text.insert(argv_text.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : argv_text) argv.push_back(a.data());
  argv.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log_path.c_str(),
                                   O_WRONLY | O_CREAT | O_APPEND, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  // Own process group: a terminal's Ctrl-C reaches the sweep only, which forwards it once.
  // Default signal actions and an empty mask, whatever the sweep (or MPI) changed.
  sigset_t all, none;
  sigfillset(&all);
  sigemptyset(&none);
  posix_spawnattr_setpgroup(&attributes, 0);
  posix_spawnattr_setsigdefault(&attributes, &all);
  posix_spawnattr_setsigmask(&attributes, &none);
  posix_spawnattr_setflags(&attributes,
                           POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
  // The case learns its sweep's process id: it stops (as on SIGTERM, with a checkpoint) when the
  // sweep is gone, instead of running on orphaned and holding the sweep's cases.
  std::vector<std::string> environment_text{std::string(kSweepParentVariable) + "=" + std::to_string(getpid())};
  for (char** e = environ; *e != nullptr; ++e)
    if (std::string_view(*e).substr(0, std::strlen(kSweepParentVariable) + 1) !=
        std::string(kSweepParentVariable) + "=")
      environment_text.emplace_back(*e);
  std::vector<char*> environment;
  for (std::string& e : environment_text) environment.push_back(e.data());
  environment.push_back(nullptr);
  pid_t pid = 0;
  const int error =
      posix_spawn(&pid, executable_.c_str(), &actions, &attributes, argv.data(), environment.data());
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  if (error != 0)
    throw std::runtime_error("cannot start " + executable_ + " (output to " + log_path +
                             "): " + std::strerror(error));
  running_.push_back({tag, pid, std::chrono::steady_clock::now(), 0});
}

void ProcessPool::forward_signals() {
  const int received = g_signals;
  for (Child& child : running_) {
    while (child.signals_forwarded < received) {
      kill(child.pid, g_last_signal);
      ++child.signals_forwarded;
    }
  }
}

std::optional<ChildExit> ProcessPool::wait() {
  if (running_.empty()) return std::nullopt;
  for (;;) {
    forward_signals();
    for (std::size_t k = 0; k < running_.size(); ++k) {
      int status = 0;
      struct rusage usage {};
      const pid_t done = wait4(running_[k].pid, &status, WNOHANG, &usage);
      if (done != running_[k].pid) continue;
      ChildExit exit;
      exit.tag = running_[k].tag;
      exit.asked_to_stop = running_[k].signals_forwarded > 0;
      exit.wall_seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - running_[k].start)
              .count();
      exit.cpu_seconds =
          static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
          1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
      if (WIFSIGNALED(status)) {
        exit.signal = WTERMSIG(status);
        exit.exit_code = 128 + exit.signal;
      } else {
        exit.exit_code = WEXITSTATUS(status);
      }
      running_.erase(running_.begin() + static_cast<std::ptrdiff_t>(k));
      return exit;
    }
    // Polling keeps this simple and safe next to MPI's own children and signals; 20 ms is
    // nothing against a case's seconds.
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

}  // namespace carom
