#include <shadelgraph/plugin/frame_description.hpp>

#include <algorithm>
#include <fstream>
#include <set>

#include <shadelgraph/plugin/registry.hpp>

namespace sg::plugin {
namespace {

std::string framed(const FrameDescription& d) {
  return "frame '" + d.name + "' (" + d.source + ")";
}

std::vector<std::string> stringOrList(const nlohmann::json& value, const std::string& where) {
  if (value.is_string()) return {value.get<std::string>()};
  if (!value.is_array()) throw FrameError(where + ": expected a pass name or a list of them");
  std::vector<std::string> names;
  for (const auto& v : value) {
    if (!v.is_string()) throw FrameError(where + ": expected pass names (strings)");
    names.push_back(v.get<std::string>());
  }
  return names;
}

void checkKeys(const nlohmann::json& object, std::initializer_list<const char*> known, const std::string& where) {
  for (const auto& [key, value] : object.items())
    if (std::none_of(known.begin(), known.end(), [&](const char* k) { return key == k; }))
      throw FrameError(where + ": unknown field '" + key + "'");
}

// The description's base expanded into one flat list of entries.
std::vector<FramePassEntry> flatten(const FrameDescription& d, const Registry& registry, int depth) {
  if (depth > 16) throw FrameError(framed(d) + ": frame bases nest deeper than 16 (a base names itself?)");
  std::vector<FramePassEntry> entries;
  if (!d.base.empty()) {
    if (!registry.hasFrame(d.base))
      throw FrameError(framed(d) + ": base frame '" + d.base + "' is not registered (known: " +
                       join(registry.frameNames()) + ")");
    entries = flatten(registry.frame(d.base), registry, depth + 1);
  }
  auto find = [&](const std::string& name) {
    return std::find_if(entries.begin(), entries.end(), [&](const FramePassEntry& e) { return e.pass == name; });
  };
  for (const auto& name : d.remove) {
    auto it = find(name);
    if (it == entries.end()) throw FrameError(framed(d) + ": remove: the base has no pass '" + name + "'");
    entries.erase(it);
  }
  for (const auto& [old, replacement] : d.replace) {
    auto it = find(old);
    if (it == entries.end()) throw FrameError(framed(d) + ": replace: the base has no pass '" + old + "'");
    it->pass = replacement;
    it->parameters = nlohmann::json::object();
  }
  entries.insert(entries.end(), d.passes.begin(), d.passes.end());
  for (const auto& [pass, values] : d.parameters) {
    auto it = find(pass);
    if (it == entries.end()) throw FrameError(framed(d) + ": parameters for '" + pass + "', which the frame does not run");
    it->parameters.update(values);
  }
  return entries;
}

// Stable topological order: unconstrained entries keep list order among
// themselves; after/before add edges, and so does what a constrained entry
// reads from a resource only one pass writes (it goes after that pass). Of
// the passes ready to go, an entry with only `after` goes first (right after
// what it follows), then the earliest in the list (so an entry with `before`
// waits until just before what it precedes).
std::vector<size_t> order(const FrameDescription& d, const std::vector<FramePassEntry>& entries,
                          const Registry& registry) {
  const size_t n = entries.size();
  std::map<std::string, size_t> index;
  for (size_t i = 0; i < n; ++i) index[entries[i].pass] = i;
  std::vector<std::vector<size_t>> next(n);
  std::vector<size_t> incoming(n, 0);
  auto edge = [&](size_t from, size_t to) {
    next[from].push_back(to);
    ++incoming[to];
  };
  auto lookup = [&](const std::string& name, const FramePassEntry& e, const char* what) {
    auto it = index.find(name);
    if (it == index.end())
      throw FrameError(framed(d) + ": pass '" + e.pass + "' is " + what + " '" + name + "', which the frame does not run");
    return it->second;
  };
  std::map<std::string, std::vector<size_t>> writers;
  for (size_t i = 0; i < n; ++i)
    for (const auto& w : registry.pass(entries[i].pass).writes) writers[w].push_back(i);
  std::optional<size_t> previous;
  for (size_t i = 0; i < n; ++i) {
    const auto& e = entries[i];
    for (const auto& a : e.after) edge(lookup(a, e, "after"), i);
    for (const auto& b : e.before) edge(i, lookup(b, e, "before"));
    if (!e.after.empty() || !e.before.empty()) {
      for (const auto& r : registry.pass(e.pass).reads)
        if (auto it = writers.find(r); it != writers.end() && it->second.size() == 1 && it->second[0] != i)
          edge(it->second[0], i);
    } else {
      if (previous) edge(*previous, i);
      previous = i;
    }
  }
  auto priority = [&](size_t i) {
    return std::pair{entries[i].after.empty() || !entries[i].before.empty() ? 1 : 0, i};
  };
  std::set<std::pair<int, size_t>> ready;
  for (size_t i = 0; i < n; ++i)
    if (incoming[i] == 0) ready.insert(priority(i));
  std::vector<size_t> result;
  while (!ready.empty()) {
    const size_t i = ready.begin()->second;
    ready.erase(ready.begin());
    result.push_back(i);
    for (const size_t j : next[i])
      if (--incoming[j] == 0) ready.insert(priority(j));
  }
  if (result.size() != n) {
    std::string stuck;
    for (size_t i = 0; i < n; ++i)
      if (incoming[i] > 0) stuck += (stuck.empty() ? "" : ", ") + entries[i].pass;
    throw FrameError(framed(d) + ": after/before constraints (and the resources they read) form a cycle among passes " +
                     stuck);
  }
  return result;
}

nlohmann::json mergeParameters(const FrameDescription& d, const PassPlugin& pass, const nlohmann::json& values) {
  nlohmann::json merged = nlohmann::json::object();
  for (const auto& p : pass.parameters) merged[p.name] = p.defaultValue;
  for (const auto& [key, value] : values.items()) {
    auto it = std::find_if(pass.parameters.begin(), pass.parameters.end(),
                           [&](const PassParameter& p) { return p.name == key; });
    if (it == pass.parameters.end()) {
      std::string known;
      for (const auto& p : pass.parameters) known += (known.empty() ? "" : ", ") + p.name;
      throw FrameError(framed(d) + ": pass '" + pass.name + "' has no parameter '" + key + "' (it has: " +
                       (known.empty() ? "none" : known) + ")");
    }
    const bool numbers = it->defaultValue.is_number() && value.is_number();
    if (!numbers && value.type() != it->defaultValue.type())
      throw FrameError(framed(d) + ": pass '" + pass.name + "' parameter '" + key + "' must be a " +
                       it->defaultValue.type_name() + ", not " + value.type_name());
    if (it->defaultValue.is_number_integer() && !value.is_number_integer())
      throw FrameError(framed(d) + ": pass '" + pass.name + "' parameter '" + key + "' must be an integer");
    merged[key] = value;
  }
  return merged;
}

}  // namespace

bool isRendererResource(const std::string& name) {
  return name == kOutputResource || name == kForwardDrawsResource || name == kDecoupledDrawsResource ||
         name == kPickResource;
}

FrameDescription parseFrameDescription(const nlohmann::json& json, const std::string& source) {
  const std::string where = "frame description " + source;
  if (!json.is_object()) throw FrameError(where + ": expected a JSON object");
  checkKeys(json, {"name", "base", "passes", "remove", "replace", "parameters", "description"}, where);
  FrameDescription d;
  d.source = source;
  d.name = json.value("name", std::filesystem::path(source).stem().string());
  if (json.contains("base")) {
    if (!json["base"].is_string()) throw FrameError(where + ": 'base' must be a frame name");
    d.base = json["base"].get<std::string>();
  }
  if (json.contains("passes")) {
    if (!json["passes"].is_array()) throw FrameError(where + ": 'passes' must be a list");
    for (size_t i = 0; i < json["passes"].size(); ++i) {
      const auto& p = json["passes"][i];
      const std::string at = where + ": passes[" + std::to_string(i) + "]";
      FramePassEntry entry;
      if (p.is_string()) {
        entry.pass = p.get<std::string>();
      } else if (p.is_object()) {
        checkKeys(p, {"pass", "parameters", "after", "before"}, at);
        if (!p.contains("pass") || !p["pass"].is_string()) throw FrameError(at + ": needs \"pass\": a pass name");
        entry.pass = p["pass"].get<std::string>();
        if (p.contains("parameters")) {
          if (!p["parameters"].is_object()) throw FrameError(at + ": 'parameters' must be an object");
          entry.parameters = p["parameters"];
        }
        if (p.contains("after")) entry.after = stringOrList(p["after"], at + ".after");
        if (p.contains("before")) entry.before = stringOrList(p["before"], at + ".before");
      } else {
        throw FrameError(at + ": expected a pass name or {\"pass\": ...}");
      }
      d.passes.push_back(std::move(entry));
    }
  }
  if (json.contains("remove")) d.remove = stringOrList(json["remove"], where + ": remove");
  if (json.contains("replace")) {
    if (!json["replace"].is_object()) throw FrameError(where + ": 'replace' must map pass names to pass names");
    for (const auto& [old, replacement] : json["replace"].items()) {
      if (!replacement.is_string()) throw FrameError(where + ": replace." + old + " must be a pass name");
      d.replace[old] = replacement.get<std::string>();
    }
  }
  if (json.contains("parameters")) {
    if (!json["parameters"].is_object()) throw FrameError(where + ": 'parameters' must map pass names to objects");
    for (const auto& [pass, values] : json["parameters"].items()) {
      if (!values.is_object()) throw FrameError(where + ": parameters." + pass + " must be an object");
      d.parameters[pass] = values;
    }
  }
  return d;
}

FrameDescription loadFrameDescription(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw FrameError(path.string() + ": cannot open the frame description");
  nlohmann::json json;
  try {
    json = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw FrameError(path.string() + ": not valid JSON: " + e.what());
  }
  return parseFrameDescription(json, path.string());
}

bool ResolvedFrame::reads(const std::string& resource) const {
  return std::any_of(passes.begin(), passes.end(), [&](const ResolvedPass& p) {
    return std::find(p.pass->reads.begin(), p.pass->reads.end(), resource) != p.pass->reads.end();
  });
}

ResolvedFrame resolveFrame(const FrameDescription& d, const Registry& registry) {
  const auto entries = flatten(d, registry, 0);
  std::set<std::string> seen;
  for (const auto& e : entries) {
    if (!registry.hasPass(e.pass))
      throw FrameError(framed(d) + ": unknown pass '" + e.pass + "' (registered: " + join(registry.passNames()) + ")");
    if (!seen.insert(e.pass).second) throw FrameError(framed(d) + ": pass '" + e.pass + "' appears twice");
  }
  ResolvedFrame frame{d.name, {}};
  std::map<std::string, std::string> writer;  // resource -> the pass that last wrote it
  for (const size_t i : order(d, entries, registry)) {
    const PassPlugin& pass = registry.pass(entries[i].pass);
    for (const auto& r : pass.reads) {
      if (isRendererResource(r) || writer.count(r)) continue;
      std::string later;
      for (const auto& e : entries) {
        const auto& w = registry.pass(e.pass).writes;
        if (std::find(w.begin(), w.end(), r) != w.end()) later = e.pass;
      }
      throw FrameError(framed(d) + ": pass '" + pass.name + "' reads '" + r + "', which " +
                       (later.empty() ? "no pass of the frame writes" : "only '" + later + "' writes, after it"));
    }
    for (const auto& w : pass.writes) writer[w] = pass.name;
    frame.passes.push_back({&pass, mergeParameters(d, pass, entries[i].parameters)});
  }
  return frame;
}

}  // namespace sg::plugin
