#include "scenarios/python/signal_guard.hpp"

#include "scenarios/run/run.hpp"

namespace carom::python {

SignalGuard::SignalGuard() {
  sigaction(SIGINT, nullptr, &interrupt_);
  sigaction(SIGTERM, nullptr, &terminate_);
  sigaction(SIGALRM, nullptr, &alarm_);
  clear_stop_request();
  install_stop_handlers();
}

SignalGuard::~SignalGuard() {
  sigaction(SIGINT, &interrupt_, nullptr);
  sigaction(SIGTERM, &terminate_, nullptr);
  sigaction(SIGALRM, &alarm_, nullptr);
}

}  // namespace carom::python
