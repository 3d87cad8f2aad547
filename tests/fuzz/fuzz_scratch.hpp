#pragma once
// The loaders take paths: each fuzz input is written to a file in a scratch
// directory of this process (removed at exit), named so the loader sees the
// type it should.
#include <cstddef>
#include <cstdint>
#include <filesystem>

namespace sg::fuzz {

// This process's scratch directory under $TMPDIR (or /tmp), created on first use.
const std::filesystem::path& scratchDir();

// Writes the input to scratchDir()/name and returns that path; aborts if it cannot.
std::filesystem::path writeInput(const char* name, const uint8_t* data, size_t size);

}  // namespace sg::fuzz
