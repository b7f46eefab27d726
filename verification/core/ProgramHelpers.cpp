#include "ProgramHelpers.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <hdf5.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

namespace sph::core_tests {

namespace {
// `command` through the shell, its stdout and stderr together.
ProgramResult runShell(const std::string& command) {
  ProgramResult r;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buffer;
  std::size_t n;
  while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) r.output.append(buffer.data(), n);
  const int status = pclose(pipe);
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}
}  // namespace

ProgramResult runSph(const std::string& arguments, const std::string& shellPrefix) {
  return runShell(shellPrefix + " '" + std::string(SPH_EXE) + "' " + arguments + " 2>&1");
}

ProgramResult compareRuns(const std::string& a, const std::string& b) {
  return runShell(std::string(SPH_PYTHON) + " '" + SPH_SOURCE_DIR + "/perf/compare_runs.py' '" + a +
                  "' '" + b + "' 2>&1");
}

int startSph(const std::vector<std::string>& arguments, const std::string& log) {
  std::vector<std::string> args{SPH_EXE};
  args.insert(args.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t pid = fork();
  if (pid == 0) {
    // Ends with the test: a test that fails or is killed (ctest's timeout) leaves no run behind.
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
    if (fd >= 0) dup2(fd, STDOUT_FILENO), dup2(fd, STDERR_FILENO);
    execv(argv[0], argv.data());
    _exit(127);
  }
  return pid;
}

int waitForSph(int pid, double seconds) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  int status = 0;
  while (waitpid(pid, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() > end) {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      return -1;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

bool waitForFile(const std::string& path, double seconds) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (!std::filesystem::exists(path)) {
    if (std::chrono::steady_clock::now() > end) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return true;
}

std::string freshOutputDirectory() {
  namespace fs = std::filesystem;
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir =
      fs::path(CORE_OUT) / (std::string(info->test_suite_name()) + "." + info->name());
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

std::string scenePath(const std::string& name) {
  return std::string(CORE_SCENES) + "/" + name;
}

std::string readText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void writeText(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
}

std::string editedScene(const std::vector<std::pair<std::string, std::string>>& edits,
                        const std::string& base) {
  std::string text = readText(scenePath(base));
  for (const auto& [from, to] : edits) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << "the base scene no longer contains '" << from << "'";
    if (at != std::string::npos) text.replace(at, from.size(), to);
  }
  const std::string path = freshOutputDirectory() + "/scene.toml";
  writeText(path, text);
  return path;
}

std::string editedScene(const std::string& from, const std::string& to) {
  return editedScene({{from, to}});
}

std::string expectRejected(const std::string& from, const std::string& to, const std::string& key,
                           const std::string& problem) {
  const std::string path = editedScene(from, to);
  const ProgramResult r = runSph("check '" + path + "'");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find(path), std::string::npos) << "file not named: " << r.output;
  EXPECT_NE(r.output.find("'" + key + "'"), std::string::npos) << "key not named: " << r.output;
  EXPECT_NE(r.output.find(problem), std::string::npos) << "problem not named: " << r.output;
  return r.output;
}

namespace {
// Opens the file read-only with HDF5's error printing off; closes it on destruction.
struct File {
  hid_t id;
  explicit File(const std::string& path) {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    id = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  }
  ~File() {
    if (id >= 0) H5Fclose(id);
  }
};

hid_t openAttribute(const File& f, const std::string& object, const std::string& name) {
  if (f.id < 0) return -1;
  if (object != "/" && H5Lexists(f.id, object.c_str(), H5P_DEFAULT) <= 0) return -1;
  if (H5Aexists_by_name(f.id, object.c_str(), name.c_str(), H5P_DEFAULT) <= 0) return -1;
  return H5Aopen_by_name(f.id, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
}
}  // namespace

std::optional<std::string> stringAttribute(const std::string& file, const std::string& object,
                                           const std::string& name) {
  File f(file);
  const hid_t a = openAttribute(f, object, name);
  if (a < 0) return std::nullopt;
  const hid_t type = H5Aget_type(a);
  std::optional<std::string> out;
  if (H5Tget_class(type) == H5T_STRING && !H5Tis_variable_str(type)) {
    std::string value(H5Tget_size(type), '\0');
    if (H5Aread(a, type, value.data()) >= 0) out = value.substr(0, value.find('\0'));
  }
  H5Tclose(type), H5Aclose(a);
  return out;
}

namespace {
template <class T>
std::optional<T> numericAttribute(const std::string& file, const std::string& object,
                                  const std::string& name, hid_t type) {
  File f(file);
  const hid_t a = openAttribute(f, object, name);
  if (a < 0) return std::nullopt;
  T value{};
  const herr_t status = H5Aread(a, type, &value);
  H5Aclose(a);
  if (status < 0) return std::nullopt;
  return value;
}
}  // namespace

std::optional<std::int64_t> integerAttribute(const std::string& file, const std::string& object,
                                             const std::string& name) {
  return numericAttribute<std::int64_t>(file, object, name, H5T_NATIVE_INT64);
}

std::optional<double> doubleAttribute(const std::string& file, const std::string& object,
                                      const std::string& name) {
  return numericAttribute<double>(file, object, name, H5T_NATIVE_DOUBLE);
}

std::optional<std::vector<std::uint64_t>> datasetShape(const std::string& file,
                                                       const std::string& dataset) {
  File f(file);
  if (f.id < 0 || H5Lexists(f.id, dataset.c_str(), H5P_DEFAULT) <= 0) return std::nullopt;
  const hid_t d = H5Dopen2(f.id, dataset.c_str(), H5P_DEFAULT);
  if (d < 0) return std::nullopt;
  const hid_t space = H5Dget_space(d);
  const int rank = H5Sget_simple_extent_ndims(space);
  std::vector<hsize_t> dims(std::max(rank, 0));
  H5Sget_simple_extent_dims(space, dims.data(), nullptr);
  H5Sclose(space), H5Dclose(d);
  return std::vector<std::uint64_t>(dims.begin(), dims.end());
}

std::vector<double> readDoubles(const std::string& file, const std::string& dataset) {
  const auto shape = datasetShape(file, dataset);
  if (!shape) return {};
  std::uint64_t n = 1;
  for (auto d : *shape) n *= d;
  std::vector<double> out(n);
  File f(file);
  const hid_t d = H5Dopen2(f.id, dataset.c_str(), H5P_DEFAULT);
  if (n > 0 && H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()) < 0)
    out.clear();
  H5Dclose(d);
  return out;
}

std::vector<std::string> groupMembers(const std::string& file, const std::string& group) {
  File f(file);
  std::vector<std::string> out;
  if (f.id < 0 || H5Lexists(f.id, group.c_str(), H5P_DEFAULT) <= 0) return out;
  const hid_t g = H5Gopen2(f.id, group.c_str(), H5P_DEFAULT);
  H5G_info_t info;
  H5Gget_info(g, &info);
  for (hsize_t k = 0; k < info.nlinks; ++k) {
    char name[256];
    H5Lget_name_by_idx(g, ".", H5_INDEX_NAME, H5_ITER_INC, k, name, sizeof name, H5P_DEFAULT);
    out.emplace_back(name);
  }
  H5Gclose(g);
  return out;
}

}  // namespace sph::core_tests
