#include "fuzz_scratch.hpp"

#include <cstdio>
#include <cstdlib>
#include <string>
#include <unistd.h>

namespace sg::fuzz {
namespace {

struct Scratch {
  std::filesystem::path path;
  Scratch() {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/sg-fuzz-XXXXXX";
    if (!mkdtemp(pattern.data())) {
      std::perror("sg-fuzz: mkdtemp");
      std::abort();
    }
    path = pattern;
  }
  ~Scratch() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
};

}  // namespace

const std::filesystem::path& scratchDir() {
  static const Scratch scratch;
  return scratch.path;
}

std::filesystem::path writeInput(const char* name, const uint8_t* data, size_t size) {
  const auto path = scratchDir() / name;
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (!file || (size && std::fwrite(data, 1, size, file) != size) || std::fclose(file) != 0) {
    std::perror("sg-fuzz: writing the input");
    std::abort();
  }
  return path;
}

}  // namespace sg::fuzz
