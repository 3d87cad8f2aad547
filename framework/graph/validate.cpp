#include <shadelgraph/graph/validate.hpp>

#include <shadelgraph/graph/dependencies.hpp>
#include <shadelgraph/graph/order.hpp>

#include <algorithm>
#include <string>
#include <string_view>

namespace sg::graph {
namespace {

std::string quoted(std::string_view name) { return "'" + std::string(name) + "'"; }
std::string str(std::string_view text) { return std::string(text); }

class Validator {
 public:
  Validator(const RenderGraph& graph, const VersionTable& versions, const DependencyGraph& deps,
            const CompileOptions& options)
      : graph_(graph), versions_(versions), deps_(deps), options_(options) {}

  std::vector<ValidationError> run() {
    for (uint32_t r = 0; r < graph_.resourceCount(); ++r) checkResource(ResourceId{r});
    for (uint32_t p = 0; p < graph_.passCount(); ++p) checkPass(PassId{p});
    checkBranches();
    checkCycles();
    return std::move(errors_);
  }

 private:
  void error(std::string pass, std::string resource, std::string message) {
    errors_.push_back({std::move(pass), std::move(resource), std::move(message)});
  }
  const std::string& nameOf(ResourceId r) const { return graph_.resource(r).name; }
  const std::string& nameOf(PassId p) const { return graph_.passName(p); }

  void checkResource(ResourceId id) {
    const ResourceDecl& r = graph_.resource(id);
    if (r.kind == ResourceKind::History &&
        (!graph_.isValid(r.historyOf) || graph_.resource(r.historyOf).kind != ResourceKind::Persistent)) {
      error("", r.name, "is the history of a resource that is not persistent");
    }
    if (r.kind == ResourceKind::History) return;  // its description is its persistent resource's
    if (r.type == ResourceType::Buffer) {
      if (r.buffer.size == 0) error("", r.name, "has zero size");
      return;
    }
    if (r.image.format == Format::Undefined) error("", r.name, "has no format");
    if (imageSizeLooksFine(r.image)) return;
    const ResolvedImageDesc d = resolveImageDesc(r.image, options_.outputWidth, options_.outputHeight);
    if (r.image.size.mode == Size::Mode::Relative && (options_.outputWidth == 0 || options_.outputHeight == 0)) {
      error("", r.name, "has a size relative to the output, but the output extent is 0x0");
    } else if (d.width == 0 || d.height == 0 || d.depth == 0) {
      error("", r.name,
            "has zero size (" + std::to_string(d.width) + "x" + std::to_string(d.height) + "x" +
                std::to_string(d.depth) + ")");
    }
    if (d.layers == 0 || d.mipLevels == 0 || d.samples == 0) {
      error("", r.name, "has zero layers, mip levels or samples");
    }
  }

  // True when the size checks below find nothing, without resolving the size
  // (a relative extent is 0 only when the output's is or the scale is not positive).
  bool imageSizeLooksFine(const ImageDesc& image) const {
    const Size& size = image.size;
    const bool sized = size.mode == Size::Mode::Relative
                           ? options_.outputWidth != 0 && options_.outputHeight != 0 && size.scaleX > 0.0f &&
                                 size.scaleY > 0.0f
                           : size.width != 0 && size.height != 0;
    return sized && image.depth != 0 && image.layers != 0 && image.mipLevels != 0 && image.samples != 0;
  }

  void checkPass(PassId id) {
    const PassDecl& pass = graph_.pass(id);
    if (!canRunOn(pass.kind, pass.queue)) {
      error(nameOf(id), "",
            "is a " + str(toString(pass.kind)) + " pass on the " + str(toString(pass.queue)) + " queue");
    }
    const auto accesses = graph_.accessesOf(id);
    for (std::size_t i = 0; i < accesses.size(); ++i) {
      const ResourceAccess& a = accesses[i];
      if (!graph_.isValid(a.resource)) {
        error(nameOf(id), "", "uses an invalid resource handle");
        continue;
      }
      // The common case (nothing to report) without the calls that build messages.
      const ResourceTraits& traits = graph_.declaration().traits[a.resource.index];
      if (!accessLooksFine(pass, traits, a)) {
        checkAccess(id, a);
      } else if (!versionLooksFine(id, traits, a)) {
        checkVersion(id, a);
      }
      // Compare with earlier accesses of the same resource in this pass (passes touch few resources).
      for (std::size_t j = 0; j < i; ++j) {
        if (accesses[j].resource == a.resource) checkAccessPair(id, accesses[j], a);
      }
    }
  }

  // True when checkAccess() finds nothing wrong but maybe the version: the same conditions, as one test.
  static bool accessLooksFine(const PassDecl& pass, const ResourceTraits& r, const ResourceAccess& a) {
    const detail::AccessTraits& t = detail::traits(a.access);
    if (a.write != t.write) return false;
    if ((r.type == ResourceType::Buffer && t.imageOnly) || (r.type == ResourceType::Image && t.bufferOnly)) return false;
    if (!allowedInPass(a.access, pass.kind)) return false;
    if (any(a.shaderStages & ~(t.shader ? shaderStagesOf(pass.kind) : ShaderStage::None))) return false;
    if (r.type == ResourceType::Image && !formatFits(r, a)) return false;
    return !(a.write && (r.kind == ResourceKind::History || r.readOnly));
  }

  // The shader stages a pass of `kind` runs.
  static ShaderStage shaderStagesOf(PassKind kind) {
    return kind == PassKind::Raster    ? ShaderStage::Vertex | ShaderStage::Fragment
           : kind == PassKind::Compute ? ShaderStage::Compute
                                       : ShaderStage::None;
  }

  // Color attachments need a color format, depth attachments a depth format.
  static bool formatFits(const ResourceTraits& r, const ResourceAccess& a) {
    const bool colorAttachment = a.access == Access::ColorAttachment || a.access == Access::ColorAttachmentRead;
    const bool depthAttachment = a.access == Access::DepthAttachment || a.access == Access::DepthRead;
    return !(colorAttachment && isDepth(r.format)) && !(depthAttachment && !isDepth(r.format));
  }

  void checkAccess(PassId passId, const ResourceAccess& a) {
    const PassDecl& pass = graph_.pass(passId);
    // Checked against the compact traits; the (large) decl is only read for a message.
    const ResourceTraits& r = graph_.declaration().traits[a.resource.index];
    const std::string_view accessName = toString(a.access);  // a table read; messages are built on error only
    if (a.write && !isWrite(a.access)) {
      error(nameOf(passId), nameOf(a.resource), "write() with the read-only access " + str(accessName) + "; use read()");
    } else if (!a.write && isWrite(a.access)) {
      error(nameOf(passId), nameOf(a.resource), "read() with the writing access " + str(accessName) + "; use write()");
    }
    if (r.type == ResourceType::Buffer && isImageOnly(a.access)) {
      error(nameOf(passId), nameOf(a.resource), "is a buffer but is accessed as " + str(accessName) + ", an image access");
    } else if (r.type == ResourceType::Image && isBufferOnly(a.access)) {
      error(nameOf(passId), nameOf(a.resource), "is an image but is accessed as " + str(accessName) + ", a buffer access");
    }
    if (!allowedInPass(a.access, pass.kind)) {
      error(nameOf(passId), nameOf(a.resource), str(accessName) + " is not possible in a " + str(toString(pass.kind)) + " pass");
    }
    checkShaderStages(passId, a);
    if (r.type == ResourceType::Image) checkFormat(passId, r, a);
    if (a.write && r.kind == ResourceKind::History) {
      error(nameOf(passId), nameOf(a.resource), "writes a history resource (last frame's copy is read-only)");
    } else if (a.write && r.readOnly) {
      error(nameOf(passId), nameOf(a.resource), "writes a read-only import");
    }
    checkVersion(passId, a);
  }

  void checkShaderStages(PassId passId, const ResourceAccess& a) {
    const PassDecl& pass = graph_.pass(passId);
    if (!isShaderAccess(a.access)) {
      if (a.shaderStages != ShaderStage::None) {
        error(nameOf(passId), nameOf(a.resource), "gives shader stages to " + str(toString(a.access)) + ", which no shader performs");
      }
      return;
    }
    if (any(a.shaderStages & ~shaderStagesOf(pass.kind))) {
      error(nameOf(passId), nameOf(a.resource),
            "uses shader stage " + toString(a.shaderStages) + " in a " + str(toString(pass.kind)) + " pass");
    }
  }

  void checkFormat(PassId passId, const ResourceTraits& r, const ResourceAccess& a) {
    const bool colorAttachment = a.access == Access::ColorAttachment || a.access == Access::ColorAttachmentRead;
    const bool depthAttachment = a.access == Access::DepthAttachment || a.access == Access::DepthRead;
    if (colorAttachment && isDepth(r.format)) {
      error(nameOf(passId), nameOf(a.resource),
            "uses the depth format " + str(toString(r.format)) + " as a color attachment (" +
                str(toString(a.access)) + ")");
    } else if (depthAttachment && !isDepth(r.format)) {
      error(nameOf(passId), nameOf(a.resource),
            "uses the color format " + str(toString(r.format)) + " as a depth attachment (" +
                str(toString(a.access)) + ")");
    }
  }

  // True when checkVersion() finds nothing: the same conditions, as one test.
  bool versionLooksFine(PassId passId, const ResourceTraits& r, const ResourceAccess& a) const {
    if (a.version == 0) return a.write || !isTransient(r.kind);
    const uint32_t slot = versions_.slot(a.resource, a.version);
    if (slot == kInvalidIndex) return false;
    const PassId producer = versions_.producer[slot];
    return producer.valid() && (producer != passId || a.write);
  }

  void checkVersion(PassId passId, const ResourceAccess& a) {
    const ResourceKind kind = graph_.declaration().traits[a.resource.index].kind;
    const uint32_t slot = versions_.slot(a.resource, a.version);
    const PassId producer = slot == kInvalidIndex ? PassId{} : versions_.producer[slot];
    if (a.version == 0) {
      if (!a.write && isTransient(kind)) error(nameOf(passId), nameOf(a.resource), "reads it before any pass writes it");
      return;
    }
    if (!producer.valid()) {
      error(nameOf(passId), nameOf(a.resource),
            (a.write ? "writes over version " : "reads version ") + std::to_string(a.version) +
                ", which no pass writes");
    } else if (producer == passId && !a.write) {
      error(nameOf(passId), nameOf(a.resource), "reads version " + std::to_string(a.version) + ", which it writes itself");
    }
  }

  // Two accesses of one resource in one pass must name the same version and fit one layout.
  void checkAccessPair(PassId passId, const ResourceAccess& first, const ResourceAccess& second) {
    const ResourceDecl& r = graph_.resource(first.resource);
    if (first.version != second.version && first.write != second.write) {
      const ResourceAccess& read = first.write ? second : first;
      const ResourceAccess& write = first.write ? first : second;
      if (versions_.producerOf(read.resource, read.version) != passId) {  // own output is reported already
        error(nameOf(passId), r.name,
              "reads version " + std::to_string(read.version) + " but writes over version " +
                  std::to_string(write.version));
      }
      return;
    }
    if (first.version != second.version) {
      error(nameOf(passId), r.name,
            std::string(first.write ? "writes over" : "reads") + " versions " + std::to_string(first.version) +
                " and " + std::to_string(second.version));
      return;
    }
    const bool storageWrites = (first.access == Access::StorageWrite || first.access == Access::StorageReadWrite) &&
                               (second.access == Access::StorageWrite || second.access == Access::StorageReadWrite);
    const bool conflictingWrites = first.write && second.write && first.access != second.access && !storageWrites;
    const bool conflictingLayouts =
        r.type == ResourceType::Image && !mergeLayouts(first.layout, second.layout).has_value();
    if (conflictingWrites || conflictingLayouts) {
      error(nameOf(passId), r.name,
            "is used as " + str(toString(first.access)) + " and " + str(toString(second.access)) +
                " in the same pass, which are incompatible");
    }
  }

  void checkBranches() {
    for (const VersionTable::BranchingWrite& b : versions_.branches) {
      const auto r = static_cast<uint32_t>(
          std::upper_bound(versions_.firstSlot.begin(), versions_.firstSlot.end(), b.slot) -
          versions_.firstSlot.begin() - 1);
      const uint32_t version = b.slot - versions_.firstSlot[r];
      const PassId first = versions_.producer[b.slot + 1];
      error(nameOf(b.pass), nameOf(ResourceId{r}),
            "writes over version " + std::to_string(version) + ", which pass " + quoted(nameOf(first)) +
                " already wrote over (branching; use the handle returned by that write)");
    }
  }

  void checkCycles() {
    const DependencyGraph& deps = deps_;
    // The usual case: every pass declared after the passes it depends on, so no cycle.
    if (std::all_of(deps.edges.begin(), deps.edges.end(), [](const Dependency& e) { return e.from < e.to; })) return;
    const std::vector<PassId> order = orderPasses(deps);
    if (order.size() == graph_.passCount()) return;

    // Passes left out all wait on another left-out pass; walking predecessors
    // among them must revisit a pass, which closes a cycle.
    std::vector<bool> leftOut(graph_.passCount(), true);
    for (const PassId p : order) leftOut[p.index] = false;
    std::vector<const Dependency*> predecessor(graph_.passCount(), nullptr);
    for (const Dependency& e : deps.edges) {
      if (leftOut[e.from.index] && leftOut[e.to.index] && !predecessor[e.to.index]) predecessor[e.to.index] = &e;
    }
    uint32_t start = 0;
    while (!leftOut[start]) ++start;
    std::vector<uint32_t> seenAt(graph_.passCount(), kInvalidIndex);
    std::vector<const Dependency*> walk;  // backwards
    uint32_t p = start;
    while (seenAt[p] == kInvalidIndex) {
      seenAt[p] = static_cast<uint32_t>(walk.size());
      walk.push_back(predecessor[p]);
      p = predecessor[p]->from.index;
    }
    // walk[seenAt[p]..] goes backwards around the cycle; reverse it to read forwards.
    std::vector<const Dependency*> cycle(walk.begin() + seenAt[p], walk.end());
    std::reverse(cycle.begin(), cycle.end());
    const auto first = std::min_element(cycle.begin(), cycle.end(),
                                        [](const Dependency* a, const Dependency* b) { return a->from < b->from; });
    std::rotate(cycle.begin(), first, cycle.end());

    std::string path;
    for (const Dependency* e : cycle) path += quoted(nameOf(e->from)) + " -> ";
    path += quoted(nameOf(cycle.front()->from));
    std::string through;
    for (const Dependency* e : cycle) through += (through.empty() ? "" : ", ") + quoted(nameOf(e->resource));
    error(nameOf(cycle.front()->from), nameOf(cycle.front()->resource),
          "is on a dependency cycle: " + path + " (through " + through + ")");
  }

  const RenderGraph& graph_;
  const VersionTable& versions_;
  const DependencyGraph& deps_;
  const CompileOptions& options_;
  std::vector<ValidationError> errors_;
};

}  // namespace

std::vector<ValidationError> validate(const RenderGraph& graph, const CompileOptions& options) {
  const VersionTable versions = indexVersions(graph);
  return validate(graph, versions, buildDependencies(graph, versions), options);
}

std::vector<ValidationError> validate(const RenderGraph& graph, const VersionTable& versions,
                                      const DependencyGraph& allPasses, const CompileOptions& options) {
  return Validator(graph, versions, allPasses, options).run();
}

}  // namespace sg::graph
