// Running the real raygrade binary from tests: exit code, standard output and error.
#pragma once

#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace raygrade::testing {

struct RunResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// A fresh folder under the system's temporary folder, removed with the object.
class TempDir {
 public:
  explicit TempDir(const std::string& tag) {
    std::string pattern =
        (std::filesystem::temp_directory_path() / ("raygrade-" + tag + "-XXXXXX"));
    if (!mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
    path_ = pattern;
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

// Runs the shell command `command` in `dir`, its standard error captured in dir/stderr.txt.
inline RunResult run_shell(const std::string& command, const std::filesystem::path& dir) {
  std::filesystem::path err = dir / "stderr.txt";
  std::string full = "cd '" + dir.string() + "' && " + command + " 2>'" + err.string() + "'";
  RunResult r;
  FILE* pipe = popen(full.c_str(), "r");
  if (!pipe) return r;
  char buffer[4096];
  std::size_t n;
  while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) r.out.append(buffer, n);
  int status = pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.err = read_text(err);
  return r;
}

// Runs `raygrade ARGS` (ARGS already quoted for the shell) in `dir`.
inline RunResult run_raygrade(const std::string& args, const std::filesystem::path& dir) {
  return run_shell("'" RAYGRADE_BINARY "' " + args, dir);
}

}  // namespace raygrade::testing
