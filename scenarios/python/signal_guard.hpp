#pragma once
/// Python keeps its own SIGINT handler (it raises KeyboardInterrupt between bytecodes, which a
/// long C++ call never reaches). While the module runs carom's machinery, carom's handlers take
/// over, as in the `carom` command: a first Ctrl-C asks the run to stop at a consistent state
/// (a run writes its checkpoint first), a second ends the process at once. Afterwards Python's
/// handlers are put back, and the caller raises KeyboardInterrupt if a stop was asked.
#include <csignal>

namespace carom::python {

class SignalGuard {
 public:
  /// Saves the handlers of SIGINT, SIGTERM and SIGALRM (the run's watch timer sets SIGALRM),
  /// forgets any stop asked before and installs carom's run handlers.
  SignalGuard();
  /// Puts the saved handlers back.
  ~SignalGuard();
  SignalGuard(const SignalGuard&) = delete;
  SignalGuard& operator=(const SignalGuard&) = delete;

 private:
  struct sigaction interrupt_ {}, terminate_ {}, alarm_ {};
};

}  // namespace carom::python
