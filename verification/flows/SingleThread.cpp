// These suites run many small problems (hundreds to a few thousand particles) on a CI machine of
// two shared cores, where OpenMP threads spend more time waiting for each other than working (a
// 17x slowdown measured under load). The results do not depend on the thread count
// (ForceEvaluation.hpp), so each suite runs on one thread.
#include <gtest/gtest.h>
#include <omp.h>

namespace {
struct SingleThread : ::testing::Environment {
  void SetUp() override { omp_set_num_threads(1); }
};
const auto* const kSingleThread = ::testing::AddGlobalTestEnvironment(new SingleThread);
}  // namespace
