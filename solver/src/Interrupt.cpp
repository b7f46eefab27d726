#include "sph/Interrupt.hpp"

#include <csignal>

namespace sph {

namespace {

volatile std::sig_atomic_t received = 0;

void record(int signal) {
  received = signal;
}

}  // namespace

void catchInterrupts() {
  struct sigaction action {};
  action.sa_handler = record;
  sigemptyset(&action.sa_mask);
  // SA_RESETHAND: the handler is used once, so a second Ctrl-C stops a run that does not stop
  // (a step that takes long) the usual way. SA_RESTART: a write in progress is not cut short.
  action.sa_flags = SA_RESETHAND | SA_RESTART;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

int interruptSignal() {
  return received;
}

}  // namespace sph
