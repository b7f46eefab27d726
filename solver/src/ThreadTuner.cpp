#include "sph/ThreadTuner.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace sph {

ThreadTuner::ThreadTuner(int maxThreads, bool fixed, int window, long shortestGap, long longestGap)
    : max_(std::max(1, maxThreads)),
      window_(std::max(1, window)),
      shortestGap_(std::max(1L, shortestGap)),
      longestGap_(std::max(shortestGap_, longestGap)),
      gap_(shortestGap_) {
  if (fixed || max_ == 1) phase_ = Phase::run, choice_ = max_, fixed_ = true;
}

double ThreadTuner::shareOnAll() const {
  const long steps = stepsOnAll_ + stepsOnOne_;
  return steps > 0 ? double(stepsOnAll_) / double(steps) : 1.0;
}

int ThreadTuner::threads() const {
  switch (phase_) {
    case Phase::trialAll:
      return max_;
    case Phase::trialOne:
      return 1;
    case Phase::run:
      return choice_;
  }
  // No default: -Wswitch names an enumerator missing above, and any other value is a bug
  // (an error here), never the last case.
  throw std::logic_error("ThreadTuner::Phase: unknown value " +
                         std::to_string(static_cast<int>(phase_)));
}

void ThreadTuner::took(double seconds) {
  (threads() == max_ ? stepsOnAll_ : stepsOnOne_) += 1;
  if (fixed_) return;
  ++inPhase_;
  const bool counted = inPhase_ > 1;  // the first step after a switch settles the threads
  switch (phase_) {
    case Phase::trialAll:
      if (counted) timeAll_ += seconds;
      if (inPhase_ > window_) phase_ = Phase::trialOne, inPhase_ = 0;
      break;
    case Phase::trialOne:
      if (counted) timeOne_ += seconds;
      if (inPhase_ > window_) {
        const int choice = timeOne_ < timeAll_ ? 1 : max_;
        gap_ = choice == choice_ ? std::min(2 * gap_, longestGap_) : shortestGap_;
        choice_ = choice;
        phase_ = Phase::run, inPhase_ = 0, timeAll_ = timeOne_ = 0;
      }
      break;
    case Phase::run:
      if (inPhase_ >= gap_) phase_ = Phase::trialAll, inPhase_ = 0;
      break;
  }
}

}  // namespace sph
