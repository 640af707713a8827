// Runs the built `tessera` CLI (TESSERA_CLI) in a shell and captures what it printed and its exit
// code, for tests of the command line.
#pragma once

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

namespace tessera::test {

struct CliResult {
  int exit_code = -1;
  std::string out;  // stdout, or stdout and stderr together when asked
};

// `arguments` is appended to the CLI path as shell text (quote paths yourself); `environment`
// ("NAME=value ...") is set for the command.
inline CliResult run_cli(const std::string& arguments, bool merge_stderr = false,
                         const std::string& environment = "") {
  const std::string command = environment + (environment.empty() ? "" : " ") + "'" + TESSERA_CLI +
                              "' " + arguments + (merge_stderr ? " 2>&1" : " 2>/dev/null");
  CliResult result;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return result;
  std::array<char, 4096> buffer{};
  std::size_t n = 0;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0)
    result.out.append(buffer.data(), n);
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

// A path as one shell word (paths of the tests hold no single quotes).
inline std::string quoted(const std::string& path) {
  return "'" + path + "'";
}

}  // namespace tessera::test
