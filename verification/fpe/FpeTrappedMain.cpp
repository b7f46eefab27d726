// The force evaluation's tests with floating-point exceptions trapped (issue 32): an invalid
// operation (0/0, inf - inf, sqrt of a negative), a division by zero or an overflow anywhere in
// the pair loop, its SIMD lanes included, stops the test with SIGFPE instead of leaving a NaN or
// an infinity to be masked or summed away. Underflow and inexact stay untrapped: both are
// expected in IEEE arithmetic (a kernel's tail, every rounding).
#include <fenv.h>
#include <gtest/gtest.h>
#include <omp.h>

namespace {

constexpr int trapped = FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW;

// Each OpenMP thread has its own floating-point environment: the traps are set on every thread
// of the team the tests use, and checked there.
void trapOnAllThreads() {
  feenableexcept(trapped);
#pragma omp parallel
  feenableexcept(trapped);
}

}  // namespace

// The traps are on: a division by zero in this process is fatal. (Killed by SIGFPE; under
// AddressSanitizer, whose handler takes the signal, reported as an FPE and exit 1. Untrapped,
// the division gives inf and the child exits 0, which fails the test.)
TEST(FloatingPointTraps, DivisionByZeroStopsTheProcess) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_DEATH(
      {
        trapOnAllThreads();
        volatile double zero = 0.0;
        volatile double q = 1.0 / zero;
        (void)q;
        std::exit(0);
      },
      "");
}

TEST(FloatingPointTraps, AreOnInEveryThread) {
  int on = 0;
#pragma omp parallel reduction(+ : on)
  on += (fegetexcept() & trapped) == trapped;
  EXPECT_EQ(on, omp_get_max_threads());
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  trapOnAllThreads();
  return RUN_ALL_TESTS();
}
