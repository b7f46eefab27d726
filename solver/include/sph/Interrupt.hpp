#pragma once
// SIGINT and SIGTERM during `sph run`: the handler only records the signal (all a handler may
// safely do), and the run loop asks between steps, so that it can write a last snapshot, mark the
// run file `interrupted` and put it in place before it exits with 128 + the signal (130, 143).
// A second signal of either kind ends the process at once, as without the handlers.
namespace sph {

void catchInterrupts();  // installs the handlers
int interruptSignal();   // the signal received since, or 0

}  // namespace sph
