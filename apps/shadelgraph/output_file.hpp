#pragma once
// Writing a whole text file so that failure is noticed: the stream's state is
// checked after the last byte is flushed and the file closed (a full disk
// fails there, not at open).
#include <string>

namespace sg::app {

// Creates missing parent directories; throws "<path>: cannot write <what> (<reason>)".
void writeTextFile(const std::string& path, const std::string& what, const std::string& text);

}  // namespace sg::app
