#pragma once
// The number of threads for a run's steps, chosen by timing them. A run's results do not depend on
// the thread count (ForceEvaluation), only its speed does, and that depends on more than the
// particle count: on the 2-vCPU VM the dam break at dx 0.01 runs in 0.6 times one thread's time
// on two threads when the machine is idle, and in several times one thread's when another
// process holds one of the cores, for then each parallel region waits for the thread that shares
// its core (perf/threads_under_load.sh).
//
// What the machine gives now is what counts, so the tuner measures now and then, in a trial of
// rounds, each a window on all threads and then one on one thread. A window is at least `window`
// steps and `windowSeconds` long, after one step to settle that is not counted: a few scheduler
// slices, so that a process that takes a core for a slice is seen by both counts alike; steps so
// slow that fewer than `window` of them take 3 windowSeconds end it early (they cost the run, and
// a count that slow needs no more to show it), and `longestWindow` steps end it whatever their
// time (a scene smaller than the dam break, whose whole run may be shorter than a trial). A round's
// ratio of the two times per step is the machine's answer for that moment. Two rounds that both
// favour one count by `clearly` decide; else the median of `rounds` rounds does (a burst of other
// work in one window decides nothing), and a tie goes to one thread, which leaves the other core to
// whoever wants it.
//
// The chosen count then runs for `gap` times the trial's wall time (so at most 1/gap of a run is
// spent on trials): the gap doubles from shortestGap to longestGap while the choice holds and its
// rounds agree (clearly), and goes back to shortestGap when it changes or the rounds disagree.
// While all threads run, two windows in a row slower per step than the trial measured by `slowdown`
// (a process took a core) start a trial at once. One thread is not watched so: it slows down by
// what other work takes from it, which a second thread would not give back. `fixed`: every step on
// all threads.
#include <vector>

namespace sph {

// How the tuner times (see above).
struct ThreadTrials {
  int window = 4;
  double windowSeconds = 0.01;
  int longestWindow = 64;  // steps
  int rounds = 3;
  double clearly = 1.25;
  double shortestGap = 8, longestGap = 64;  // in trial wall times
  double slowdown = 1.5;
};

class ThreadTuner {
 public:
  using Settings = ThreadTrials;
  explicit ThreadTuner(int maxThreads, bool fixed = false, ThreadTrials settings = {});

  int threads() const;        // for the next step
  void took(double seconds);  // the wall time of the step just run on threads()

  double shareOnAll() const;  // of the steps so far (1 before the first)
  long trials() const { return trials_; }

 private:
  enum class Phase { trialAll, trialOne, run };
  struct Window {    // of one thread count
    long seen = 0;   // steps, the first (to settle) included
    long steps = 0;  // counted
    double seconds = 0;
    double perStep() const { return seconds / double(steps); }
  };
  bool add(Window& w, double seconds) const;  // true once w is full
  std::vector<double> ratios() const;         // all threads' time per step over one's, by round
  bool unanimous() const;                     // every round so far favours one count by `clearly`
  bool clear() const;                         // two rounds or more, unanimous
  void startTrial();
  void decide();

  int max_;
  Settings s_;
  Phase phase_ = Phase::trialAll;
  Window current_;
  std::vector<double> perStepAll_, perStepOne_;  // the trial's rounds so far
  double trialSeconds_ = 0, runSeconds_ = 0, gap_;
  double reference_ = 0;  // the chosen count's time per step in the last trial
  int slowWindows_ = 0;   // in a row
  int choice_ = 0;        // 0 before the first trial
  bool fixed_ = false;
  long stepsOnAll_ = 0, stepsOnOne_ = 0, trials_ = 0;
};

}  // namespace sph
