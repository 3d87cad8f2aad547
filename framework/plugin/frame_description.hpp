#pragma once
// A frame description: which registered passes a frame runs, in what order
// (or with what after/before constraints) and with which parameters. The
// built-in frames are descriptions registered by their packages; a user's
// frame is a JSON file (docs/composing-frames.md):
//
//   {"name": "outlined", "base": "decoupled",
//    "passes": [{"pass": "outline", "after": "tonemap", "parameters": {"width": 2}}],
//    "remove": ["alpha-blend"], "replace": {"exposure": "fixed-exposure"},
//    "parameters": {"composite": {"filter": 1}}}
//
// resolveFrame turns a description into the ordered passes with their
// parameters, or throws FrameError with one line naming the frame, the pass
// and the resource.
#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <shadelgraph/plugin/pass_plugin.hpp>

namespace sg::plugin {

class Registry;

class FrameError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct FramePassEntry {
  std::string pass;
  nlohmann::json parameters = nlohmann::json::object();
  std::vector<std::string> after, before;  // names of other passes of the frame
};

struct FrameDescription {
  std::string name;
  std::string source = "built-in";  // where it came from, for messages (a file path)
  std::string base;                 // a registered frame this one edits; empty: none
  std::vector<FramePassEntry> passes;  // in order; after a base's passes
  std::vector<std::string> remove;     // passes of the base to drop
  std::map<std::string, std::string> replace;  // pass of the base -> the pass taking its place
  std::map<std::string, nlohmann::json> parameters;  // per pass: values over its entry's
};

// Parses the JSON form; throws FrameError naming `source` and the field.
FrameDescription parseFrameDescription(const nlohmann::json& json, const std::string& source);
FrameDescription loadFrameDescription(const std::filesystem::path& path);

struct ResolvedPass {
  const PassPlugin* pass = nullptr;
  nlohmann::json parameters;  // every parameter of the pass: its default or the frame's value
};

struct ResolvedFrame {
  std::string name;
  std::vector<ResolvedPass> passes;  // in execution order
  bool reads(const std::string& resource) const;
};

// Expands the base, checks pass and parameter names and types, orders the
// passes (list order, then after/before; a cycle is an error) and checks that
// every read resource is written by an earlier pass or by the renderer.
ResolvedFrame resolveFrame(const FrameDescription& description, const Registry& registry);

}  // namespace sg::plugin
