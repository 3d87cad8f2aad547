#pragma once
// Everything that can go wrong while loading a glTF or a scene file is
// reported as one exception type with a one-line message "<file>: <what>",
// so a CLI or test can print it and carry on: bad input never crashes.
#include <filesystem>
#include <stdexcept>
#include <string>

namespace sg::scene {

class SceneError : public std::runtime_error {
 public:
  SceneError(const std::filesystem::path& file, const std::string& what)
      : std::runtime_error(file.string() + ": " + what), file_(file), detail_(what) {}

  const std::filesystem::path& file() const { return file_; }
  // The message without the file name.
  const std::string& detail() const { return detail_; }

 private:
  std::filesystem::path file_;
  std::string detail_;
};

}  // namespace sg::scene
