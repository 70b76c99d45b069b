// Ctrl-C (SIGINT) and SIGTERM as a request to stop a run cleanly: the handler only sets a flag,
// which the step loop reads between steps (analysis/simulation.cpp); the run then ends as one
// that stopped, with its plots, summary.json and a checkpoint written. A second signal ends the
// process at once (the default action is restored by the first).
#pragma once

namespace geompm {

/// Installs the handler of SIGINT and SIGTERM (the command line does, not the library).
void install_interrupt_handler();

/// Whether a signal asked the run to stop.
bool interrupt_requested();

/// The signal's name ("SIGINT", "SIGTERM") for messages; "" when none came.
const char* interrupt_signal_name();

/// As if the signal `signal_number` had come (tests), or, with 0, as if none had.
void set_interrupt_requested(int signal_number);

}  // namespace geompm
