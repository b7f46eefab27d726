#include "sph/ThreadTuner.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace sph {

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

ThreadTuner::ThreadTuner(int maxThreads, bool fixed, Settings settings)
    : max_(std::max(1, maxThreads)), s_(settings) {
  s_.window = std::max(1, s_.window);
  s_.longestWindow = std::max(s_.window, s_.longestWindow);
  s_.rounds = std::max(1, s_.rounds);
  s_.shortestGap = std::max(0.0, s_.shortestGap);
  s_.longestGap = std::max(s_.shortestGap, s_.longestGap);
  gap_ = s_.shortestGap;
  if (fixed || max_ == 1) phase_ = Phase::run, choice_ = max_, fixed_ = true;
  perStepAll_.reserve(s_.rounds), perStepOne_.reserve(s_.rounds);
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

bool ThreadTuner::add(Window& w, double seconds) const {
  if (w.seen++ > 0) w.steps += 1, w.seconds += seconds;  // the first step settles the threads
  // Steps so slow that fewer than `window` of them fill three windows' time end the window
  // early: a count that slow needs no more of them to show it, and each costs the run.
  if (w.steps >= s_.window) return w.seconds >= s_.windowSeconds || w.steps >= s_.longestWindow;
  return s_.windowSeconds > 0 && w.steps >= 1 && w.seconds >= 3 * s_.windowSeconds;
}

void ThreadTuner::startTrial() {
  phase_ = Phase::trialAll, current_ = Window();
  perStepAll_.clear(), perStepOne_.clear();
  trialSeconds_ = 0;
}

std::vector<double> ThreadTuner::ratios() const {
  std::vector<double> ratio;
  for (std::size_t r = 0; r < perStepOne_.size(); ++r)
    ratio.push_back(perStepAll_[r] / perStepOne_[r]);
  return ratio;
}

bool ThreadTuner::unanimous() const {
  const auto ratio = ratios();
  if (ratio.empty()) return false;
  const auto [low, high] = std::minmax_element(ratio.begin(), ratio.end());
  return *high < 1 / s_.clearly || *low > s_.clearly;
}

bool ThreadTuner::clear() const {
  return perStepOne_.size() >= 2 && unanimous();
}

void ThreadTuner::decide() {
  const int choice = median(ratios()) < 1.0 ? max_ : 1;
  // A choice the rounds did not agree on (a burst of other work in some window) is tried again
  // after the shortest gap: where a stall of the host decided one thread on a machine that gives
  // two, a doubled gap kept the run on one thread for seconds (issue 37).
  gap_ = choice == choice_ && unanimous() ? std::min(2 * gap_, s_.longestGap) : s_.shortestGap;
  choice_ = choice;
  reference_ = median(choice == 1 ? perStepOne_ : perStepAll_);
  phase_ = Phase::run, current_ = Window(), runSeconds_ = 0, slowWindows_ = 0;
  ++trials_;
}

void ThreadTuner::took(double seconds) {
  (threads() == max_ ? stepsOnAll_ : stepsOnOne_) += 1;
  if (fixed_) return;
  switch (phase_) {
    case Phase::trialAll:
      trialSeconds_ += seconds;
      if (add(current_, seconds)) {
        perStepAll_.push_back(current_.perStep());
        phase_ = Phase::trialOne, current_ = Window();
      }
      break;
    case Phase::trialOne:
      trialSeconds_ += seconds;
      if (add(current_, seconds)) {
        perStepOne_.push_back(current_.perStep());
        current_ = Window();
        if (clear() || static_cast<int>(perStepOne_.size()) >= s_.rounds)
          decide();
        else
          phase_ = Phase::trialAll;
      }
      break;
    case Phase::run:
      runSeconds_ += seconds;
      if (add(current_, seconds)) {
        // All threads only (see the header).
        const bool slow = choice_ == max_ && current_.perStep() > s_.slowdown * reference_;
        slowWindows_ = slow ? slowWindows_ + 1 : 0;
        current_ = Window();
        current_.seen = 1;  // no change of count: every step of the next window counts
        if (slowWindows_ >= 2) {
          choice_ = 0;  // the machine changed: the next gap is the shortest, whatever the choice
          startTrial();
          break;
        }
      }
      if (runSeconds_ >= gap_ * trialSeconds_) startTrial();
      break;
  }
}

}  // namespace sph
