#include <shadelgraph/scene/input_limits.hpp>

namespace sg::scene::detail {

std::optional<std::string> jsonDepthError(std::string_view json, size_t maxDepth) {
  size_t depth = 0;
  bool inString = false;
  for (size_t i = 0; i < json.size(); ++i) {
    const char c = json[i];
    if (inString) {
      if (c == '\\') ++i;  // the escaped character cannot end the string
      else if (c == '"') inString = false;
      continue;
    }
    switch (c) {
      case '"': inString = true; break;
      case '{':
      case '[':
        if (++depth > maxDepth)
          return "JSON nested deeper than " + std::to_string(maxDepth) + " levels (at byte " + std::to_string(i) + ")";
        break;
      case '}':
      case ']':
        if (depth > 0) --depth;  // unbalanced text is the parser's to report
        break;
      default: break;
    }
  }
  return std::nullopt;
}

std::string capText(std::string_view text, size_t maxChars) {
  if (text.size() <= maxChars) return std::string(text);
  size_t cut = maxChars;
  while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;  // not inside a UTF-8 character
  return std::string(text.substr(0, cut)) + "... (" + std::to_string(text.size() - cut) + " more characters)";
}

void capWarnings(std::vector<std::string>& warnings, size_t maxCount) {
  for (std::string& warning : warnings) warning = capText(warning, 400);
  if (warnings.size() <= maxCount) return;
  const size_t more = warnings.size() - maxCount;
  warnings.resize(maxCount);
  warnings.push_back("and " + std::to_string(more) + " more warnings");
}

}  // namespace sg::scene::detail
