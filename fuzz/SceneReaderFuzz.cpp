// libFuzzer target for the run-scene reader (issue 32): any text given to `sph check` or `sph run`
// is either accepted or refused with a SceneError that names the file; nothing else may escape
// (an uncaught exception aborts, which libFuzzer reports as a crash), and no input may crash or
// hang the reader. (The packing reader, PackingScene.cpp, reads its tables through the same
// SceneReader.hpp, but it builds the container's lattice as it checks a scene, which a dx that its
// index bound lets through can keep busy beyond the fuzzer's timeout: not fuzzed here. What `sph
// check` does after reading, the estimates of RunBudget.hpp, builds the start: the run-mutation
// driver, fuzz/run_mutants.py, covers it through the program.)
#include <cstddef>
#include <cstdint>
#include <string>

#include "sph/Scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    (void)sph::parseScene(text, "fuzz.toml");
  } catch (const sph::SceneError&) {
  }
  return 0;
}
