#pragma once
// Clean interruption (issue 16): SIGINT, SIGTERM and SIGHUP ask a run to stop instead of killing
// it, so every output written so far is finished and well-formed; the run loops poll
// interruptRequested() between frames. SIGPIPE is ignored, so a closed pipe on stdout is a write
// error, not sudden death. A second signal of the same kind ends the process at once.
namespace dynanav {

/// Installs the handlers (idempotent; the CLI calls it before a run).
void installInterruptHandlers();
/// True once a handled signal has arrived.
[[nodiscard]] bool interruptRequested();
/// The signal that asked to stop (0 = none).
[[nodiscard]] int interruptSignal();
/// For tests and callers that want to stop a run themselves.
void requestInterrupt(int signal_number);

}  // namespace dynanav
