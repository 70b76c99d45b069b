#include "geompm/core/interrupt.hpp"

#include <csignal>

namespace geompm {

namespace {

volatile std::sig_atomic_t requested_by = 0;  // the signal's number, 0 for none

extern "C" void on_interrupt(int signal_number) {
  requested_by = signal_number;
  std::signal(signal_number, SIG_DFL);  // async-signal-safe: the next one ends the process
}

}  // namespace

void install_interrupt_handler() {
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
}

bool interrupt_requested() { return requested_by != 0; }

const char* interrupt_signal_name() {
  switch (requested_by) {
    case 0:
      return "";
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    default:
      return "a signal";
  }
}

void set_interrupt_requested(int signal_number) { requested_by = signal_number; }

}  // namespace geompm
