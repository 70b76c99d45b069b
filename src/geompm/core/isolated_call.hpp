// Run a piece of work whose code geompm does not own (a third-party file reader) in a child
// process, so that a crash inside it on malformed input becomes a clear input error instead of
// taking geompm down. The work returns its result as bytes (a ByteWriter's), which travel back
// through a pipe; an InputError it throws travels back as its message.
#pragma once

#include <functional>
#include <string>

namespace geompm {

/// Runs `work` in a forked child process and returns the bytes it returned. An InputError the
/// work throws is rethrown here with its message; any other exception becomes an InputError
/// naming `what` and the exception's message; a child that dies (a signal: a segmentation fault
/// in the reader) or exits without an answer becomes an InputError saying that reading `what`
/// crashed. The work must not start threads that the parent needs, nor touch MPI: the child
/// leaves with _exit, running no exit handlers.
std::string call_isolated(const std::string& what, const std::function<std::string()>& work);

}  // namespace geompm
