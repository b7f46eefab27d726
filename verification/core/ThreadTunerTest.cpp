// The thread count a run's steps take (ThreadTuner, issue 7), on made-up step times: the tuner
// must settle on the faster count, ignore a trial's first step, and space its trials out while
// the choice holds.
#include <gtest/gtest.h>

#include <functional>
#include <vector>

#include "sph/ThreadTuner.hpp"

namespace {

// The thread counts of `steps` steps whose wall time is stepTime(threads, step).
std::vector<int> counts(sph::ThreadTuner& tuner, int steps,
                        const std::function<double(int, int)>& stepTime) {
  std::vector<int> used;
  for (int k = 0; k < steps; ++k) {
    used.push_back(tuner.threads());
    tuner.took(stepTime(used.back(), k));
  }
  return used;
}

TEST(ThreadTuner, OneThreadAvailableMeansOne) {
  sph::ThreadTuner tuner(1);
  for (int t : counts(tuner, 100, [](int, int) { return 1.0; })) EXPECT_EQ(t, 1);
  EXPECT_EQ(tuner.shareOnAll(), 1.0);  // all of the one thread
}

TEST(ThreadTuner, FixedMeansAllThreadsEveryStep) {
  sph::ThreadTuner tuner(2, true);
  for (int t : counts(tuner, 100, [](int threads, int) { return threads == 1 ? 1.0 : 2.0; }))
    EXPECT_EQ(t, 2);
  EXPECT_EQ(tuner.shareOnAll(), 1.0);
}

TEST(ThreadTuner, TrialsThenTheFasterCount) {
  // window 4, gap 10: 5 steps on all (the first not counted), 5 on one, then 10 on the faster.
  for (const bool oneFaster : {true, false}) {
    sph::ThreadTuner tuner(2, false, 4, 10, 10);
    const auto used = counts(
        tuner, 20, [&](int threads, int) { return (threads == 1) == oneFaster ? 1.0 : 2.0; });
    for (int k = 0; k < 5; ++k) EXPECT_EQ(used[k], 2) << k;
    for (int k = 5; k < 10; ++k) EXPECT_EQ(used[k], 1) << k;
    for (int k = 10; k < 20; ++k) EXPECT_EQ(used[k], oneFaster ? 1 : 2) << k;
  }
}

TEST(ThreadTuner, FirstStepOfATrialIsNotCounted) {
  // All threads faster, but the first step on them (waking the threads) is slow.
  sph::ThreadTuner tuner(2, false, 4, 10, 10);
  const auto used = counts(tuner, 11, [](int threads, int k) {
    return threads == 1 ? 1.0 : k == 0 ? 100 : 0.5;
  });
  EXPECT_EQ(used[10], 2);
}

TEST(ThreadTuner, TrialsSpaceOutWhileTheChoiceHolds) {
  // window 1 (2 steps a count), gaps 4, 8, 16, 16: trials start at steps 0, 8, 20, 40, 60.
  sph::ThreadTuner tuner(2, false, 1, 4, 16);
  const auto used = counts(tuner, 70, [](int threads, int) { return threads == 1 ? 1.0 : 0.5; });
  std::vector<int> trialsOnOne;
  for (int k = 0; k < 70; ++k)
    if (used[k] == 1) trialsOnOne.push_back(k);
  EXPECT_EQ(trialsOnOne, (std::vector<int>{2, 3, 10, 11, 22, 23, 42, 43, 62, 63}));
}

TEST(ThreadTuner, AChangedChoiceShortensTheGapAgain) {
  // One thread faster for the first 30 steps, then all threads.
  sph::ThreadTuner tuner(2, false, 1, 4, 16);
  const auto used =
      counts(tuner, 60, [](int threads, int k) { return (threads == 1) == (k < 30) ? 1.0 : 2.0; });
  // Trials at 0 (gap 4: run 4-7), 8 (gap 8: 12-19), 20 (gap 16: 24-39), 40: all faster now, gap
  // back to 4: run 44-47 on all threads.
  for (int k = 24; k < 40; ++k) EXPECT_EQ(used[k], 1) << k;
  for (int k = 44; k < 48; ++k) EXPECT_EQ(used[k], 2) << k;
  EXPECT_EQ(used[48], 2);  // the next trial, on all threads first
  EXPECT_EQ(used[50], 1);
}

}  // namespace
