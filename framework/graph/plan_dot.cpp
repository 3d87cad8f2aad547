#include <shadelgraph/graph/plan_dump.hpp>

#include <sstream>
#include <string_view>

namespace sg::graph {
namespace {

std::string quoted(std::string_view text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + '"';
}

std::string_view queueColor(QueueClass queue) {
  switch (queue) {
    case QueueClass::Graphics: return "#9ecae1";
    case QueueClass::AsyncCompute: return "#fdae6b";
    case QueueClass::Transfer: return "#a1d99b";
  }
  return "white";
}

std::string versionNode(ResourceId r, uint32_t version) {
  return "r" + std::to_string(r.index) + "v" + std::to_string(version);
}

}  // namespace

std::string toDot(const CompiledPlan& plan) {
  std::ostringstream out;
  out << "digraph plan {\n  rankdir=LR;\n  node [fontname=\"sans-serif\"];\n";
  for (uint32_t p = 0; p < plan.passes.size(); ++p) {
    const PlannedPass& pass = plan.passes[p];
    out << "  p" << p << " [shape=box, style=\"filled" << (pass.culled ? ",dashed" : "") << "\", fillcolor=\""
        << queueColor(pass.queue) << "\", label=" << quoted(pass.name) << "];\n";
  }
  // Resource versions that some pass touches.
  std::vector<std::vector<bool>> drawn(plan.resources.size());
  const auto node = [&](ResourceId r, uint32_t version) {
    std::vector<bool>& versions = drawn[r.index];
    if (versions.size() <= version) versions.resize(version + 1, false);
    if (!versions[version]) {
      versions[version] = true;
      out << "  " << versionNode(r, version) << " [shape=ellipse, label="
          << quoted(plan.resources[r.index].name + " v" + std::to_string(version)) << "];\n";
    }
    return versionNode(r, version);
  };
  for (uint32_t p = 0; p < plan.passes.size(); ++p) {
    const PlannedPass& pass = plan.passes[p];
    const std::string_view style = pass.culled ? " [style=dashed]" : "";
    for (const ResourceAccess& a : plan.accessesOf(PassId{p})) {
      // node() may print the version's declaration, so call it before the edge line.
      if (a.write) {
        const std::string target = node(a.resource, a.version + 1);
        out << "  p" << p << " -> " << target << style << ";\n";
      } else {
        const std::string source = node(a.resource, a.version);
        out << "  " << source << " -> p" << p << style << ";\n";
      }
    }
  }
  out << "}\n";
  return out.str();
}

}  // namespace sg::graph
