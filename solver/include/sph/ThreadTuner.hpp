#pragma once
// The number of threads for a run's steps, chosen by timing them. A run's results do not depend on
// the thread count (ForceEvaluation), only its speed does, and that depends on more than the
// particle count: on the 2-vCPU VM the dam break at dx 0.01 took 2.5-2.8 s on two threads when the
// vCPUs shared a cache and 4.3-4.7 s when they did not (perf/CoreRoundTrip.hpp), against 3.8 s on
// one; with sleeping idle threads (OMP_WAIT_POLICY=passive) two threads lose to one at that size.
//
// A trial times `window` steps on all threads and `window` on one (each after one step to settle,
// not counted); the faster count then runs until the next trial. The gap between trials doubles
// while the choice stays the same (a trial on the slower count costs time), up to `longestGap`
// steps, and goes back to `shortestGap` when it changes. `fixed`: every step on all threads.
namespace sph {

class ThreadTuner {
 public:
  explicit ThreadTuner(int maxThreads, bool fixed = false, int window = 24, long shortestGap = 512,
                       long longestGap = 8192);

  int threads() const;        // for the next step
  void took(double seconds);  // the wall time of the step just run on threads()

  double shareOnAll() const;  // of the steps so far (1 before the first)

 private:
  enum class Phase { trialAll, trialOne, run };
  int max_, window_;
  long shortestGap_, longestGap_, gap_;
  Phase phase_ = Phase::trialAll;
  long inPhase_ = 0;  // steps taken in this phase
  double timeAll_ = 0, timeOne_ = 0;
  int choice_ = 0;  // 0 before the first trial
  bool fixed_ = false;
  long stepsOnAll_ = 0, stepsOnOne_ = 0;
};

}  // namespace sph
