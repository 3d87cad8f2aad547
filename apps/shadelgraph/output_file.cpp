#include "output_file.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace sg::app {

void writeTextFile(const std::string& path, const std::string& what, const std::string& text) {
  const std::filesystem::path file(path);
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
  errno = 0;
  std::ofstream out(file, std::ios::binary);
  if (out) out.write(text.data(), std::streamsize(text.size()));
  if (out) out.flush();
  if (out.is_open()) out.close();
  if (out.fail())
    throw std::runtime_error(path + ": cannot write " + what + " (" + (errno ? std::strerror(errno) : "write failed") +
                             ")");
}

}  // namespace sg::app
