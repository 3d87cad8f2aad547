#pragma once
// Runs the shadelgraph binary as a user would, through the shell, and
// collects its exit code and output.
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace sg::test {

struct CliRun {
  int exitCode = -1;
  std::string output;  // what the command wrote to the pipe
};

// A shell command line; its stdout is collected.
inline CliRun runShell(const std::string& command) {
  CliRun r;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buffer;
  size_t n;
  while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) r.output.append(buffer.data(), n);
  const int status = pclose(pipe);
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

// shadelgraph `args`. stderrTo: where its stderr goes (merged into the output
// by default); redirect: appended last, e.g. " >/dev/full" to send stdout elsewhere.
inline CliRun runCli(const std::string& args, const std::string& stderrTo = "&1", const std::string& redirect = "") {
  return runShell(std::string(SG_CLI) + " " + args + " 2>" + stderrTo + redirect);
}

struct CliOutputs {
  int exitCode = -1;
  std::string out, err;
};

// shadelgraph `args` with stdout and stderr apart (stderr through `errFile`).
inline CliOutputs runCliApart(const std::string& args, const std::filesystem::path& errFile) {
  const CliRun r = runShell(std::string(SG_CLI) + " " + args + " 2>" + errFile.string());
  std::ifstream in(errFile, std::ios::binary);
  return {r.exitCode, r.output, std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>())};
}

}  // namespace sg::test
