#include <shadelgraph/graph/validate.hpp>

#include <shadelgraph/graph/dependencies.hpp>
#include <shadelgraph/graph/order.hpp>

#include <algorithm>
#include <array>
#include <string>
#include <string_view>

namespace sg::graph {
namespace {

std::string quoted(std::string_view name) { return "'" + std::string(name) + "'"; }
std::string str(std::string_view text) { return std::string(text); }

// The shader stages a pass of `kind` runs.
constexpr ShaderStage shaderStagesOf(PassKind kind) {
  return kind == PassKind::Raster    ? ShaderStage::Vertex | ShaderStage::Fragment
         : kind == PassKind::Compute ? ShaderStage::Compute
                                     : ShaderStage::None;
}

// What is allowed for one access in one kind of pass: the checks of
// checkAccess() (but the version's) precomputed from the access traits.
struct AccessRule {
  // Bit resourceClass * 4 + write * 2 + notWritable is set when that combination
  // passes: resourceClass 0 buffer, 1 image of a color format, 2 of a depth
  // format; write as declared (read() or write()); notWritable for history
  // resources and read-only imports.
  uint16_t fineFor = 0;
  ShaderStage stages = ShaderStage::None;  // the shader stages it may name
};
constexpr std::size_t kPassKinds = 3;
constexpr std::size_t kAccesses = detail::kAccessTraits.size();

constexpr AccessRule ruleFor(Access access, PassKind kind) {
  const detail::AccessTraits& t = detail::traits(access);
  const bool colorAttachment = access == Access::ColorAttachment || access == Access::ColorAttachmentRead;
  const bool depthAttachment = access == Access::DepthAttachment || access == Access::DepthRead;
  AccessRule rule;
  rule.stages = t.shader ? shaderStagesOf(kind) : ShaderStage::None;
  for (uint32_t resourceClass = 0; resourceClass < 3; ++resourceClass) {
    const bool buffer = resourceClass == 0;
    const bool depthFormat = resourceClass == 2;
    const bool typeFits = buffer ? !t.imageOnly : !t.bufferOnly;
    const bool formatFits = buffer || (!(colorAttachment && depthFormat) && !(depthAttachment && !depthFormat));
    for (uint32_t write = 0; write < 2; ++write) {
      for (uint32_t notWritable = 0; notWritable < 2; ++notWritable) {
        const bool fine = (write != 0) == t.write && typeFits && allowedInPass(access, kind) && formatFits &&
                          !(write != 0 && notWritable != 0);
        if (fine) rule.fineFor |= static_cast<uint16_t>(1u << (resourceClass * 4 + write * 2 + notWritable));
      }
    }
  }
  return rule;
}
constexpr std::array<std::array<AccessRule, kAccesses>, kPassKinds> kAccessRules = [] {
  std::array<std::array<AccessRule, kAccesses>, kPassKinds> rules{};
  for (std::size_t k = 0; k < kPassKinds; ++k) {
    for (std::size_t a = 0; a < kAccesses; ++a) {
      rules[k][a] = ruleFor(static_cast<Access>(a), static_cast<PassKind>(k));
    }
  }
  return rules;
}();
// canRunOn() as a table read (a switch on the random pass kinds mispredicts):
// bit q of kQueuesFor[kind] is set when a pass of `kind` can run on queue class q.
constexpr std::array<uint8_t, kPassKinds> kQueuesFor = [] {
  std::array<uint8_t, kPassKinds> queues{};
  for (std::size_t k = 0; k < kPassKinds; ++k) {
    for (uint32_t q = 0; q < kQueueClassCount; ++q) {
      if (canRunOn(static_cast<PassKind>(k), static_cast<QueueClass>(q))) queues[k] |= static_cast<uint8_t>(1u << q);
    }
  }
  return queues;
}();
bool runsOn(PassKind kind, QueueClass queue) {
  return ((kQueuesFor[static_cast<std::size_t>(kind)] >> queueIndex(queue)) & 1u) != 0;
}

class Validator {
 public:
  Validator(const RenderGraph& graph, const VersionTable& versions, const DependencyGraph& deps,
            const CompileOptions& options)
      : graph_(graph),
        versions_(versions),
        deps_(deps),
        options_(options),
        outputSized_((options.outputWidth != 0) & (options.outputHeight != 0)) {}

  std::vector<ValidationError> run() {
    const uint32_t resourceCount = graph_.resourceCount();
    facts_.resize(resourceCount);
    for (uint32_t r = 0; r < resourceCount; ++r) {
      checkResource(ResourceId{r});
      facts_[r] = {kInvalidIndex, shapeOf(graph_.declaration().traits[r])};
    }
    checkPasses();
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

  // The common case (nothing to report) as one test: both the buffer's and the
  // image's conditions are computed and the resource's type picks one, so that
  // a random mix of buffers and images costs no mispredicted branch.
  void checkResource(ResourceId id) {
    const ResourceDecl& r = graph_.resource(id);
    const bool isBuffer = r.type == ResourceType::Buffer;
    const bool bufferFine = r.buffer.size != 0;
    const bool imageFine = (r.image.format != Format::Undefined) & imageSizeLooksFine(r.image);
    const bool fine = (r.kind != ResourceKind::History) & ((isBuffer & bufferFine) | (!isBuffer & imageFine));
    if (!fine) [[unlikely]] reportResource(id);
  }

  // What checkResource() reports, in order (off the common path).
  [[gnu::noinline]] void reportResource(ResourceId id) {
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
  // (`&` and `|`, not `&&` and `||`: every condition is computed, none branches.)
  bool imageSizeLooksFine(const ImageDesc& image) const {
    const Size& size = image.size;
    const bool relative = size.mode == Size::Mode::Relative;
    const bool relativeSized = outputSized_ & (size.scaleX > 0.0f) & (size.scaleY > 0.0f);
    const bool absoluteSized = (size.width != 0) & (size.height != 0);
    const bool sized = (relative & relativeSized) | ((!relative) & absoluteSized);
    const uint32_t fewest = std::min(std::min(image.depth, image.layers), std::min(image.mipLevels, image.samples));
    return sized & (fewest != 0);
  }

  // The common case (nothing to report) without a branch per condition:
  // every access's conditions are folded into its pass's flag (table reads and
  // arithmetic on bools), walking all accesses in one loop. A resource named
  // twice in a pass (whose accesses must then be compared pairwise) marks the
  // pass too. Only the passes so marked take the detailed walk, in pass
  // order, which reports what it finds in order.
  void checkPasses() {
    const uint32_t passCount = graph_.passCount();
    const PassDecl* passes = graph_.declaration().passes.data();
    std::vector<uint8_t> fine(passCount);
    for (uint32_t p = 0; p < passCount; ++p) fine[p] = runsOn(passes[p].kind, passes[p].queue);
    const uint32_t resourceCount = graph_.resourceCount();
    ResourceFacts* facts = facts_.data();
    uint8_t* passFine = fine.data();
    const uint32_t* firstSlot = versions_.firstSlot.data();
    const PassId* producers = versions_.producer.data();
    forEachAccess(graph_, versions_, [&](uint32_t p, const ResourceAccess& a) __attribute__((always_inline)) {
      const uint32_t r = a.resource.index;
      if (r >= resourceCount) [[unlikely]] {  // !isValid()
        passFine[p] = 0;
        return;
      }
      const AccessRule& rule = kAccessRules[static_cast<std::size_t>(passes[p].kind)][static_cast<std::size_t>(a.access)];
      passFine[p] &= (facts[r].namedBy != p) & accessIsFine(rule, PassId{p}, a, facts[r].shape, firstSlot, producers);
      facts[r].namedBy = p;
    });
    for (uint32_t p = 0; p < passCount; ++p) {
      if (!fine[p]) [[unlikely]] reportPass(PassId{p});
    }
  }

  // What accessIsFine() needs of a resource, looked up once per resource:
  // resourceClass * 4 + notWritable (see AccessRule), plus kTransientShape.
  static constexpr uint8_t kTransientShape = 16;
  static uint8_t shapeOf(const ResourceTraits& r) {
    // (Arithmetic on bools, not `?:`: buffers and images come in random order.)
    const uint32_t image = r.type == ResourceType::Image;
    const uint32_t depthFormat = isDepth(r.format);
    const uint32_t resourceClass = image + (image & depthFormat);
    const uint32_t notWritable = (r.kind == ResourceKind::History) | r.readOnly;
    const uint32_t transient = (r.kind == ResourceKind::TransientImage) | (r.kind == ResourceKind::TransientBuffer);
    return static_cast<uint8_t>(resourceClass * 4 + notWritable + transient * kTransientShape);
  }

  // True when checkAccess() (and with it checkVersion()) finds nothing: the same
  // conditions, each computed, combined with `&` (no branch per condition).
  // (Raw pointers, in the caller's registers: its byte stores would make the
  // compiler reload the version table's vectors after each.)
  static bool accessIsFine(const AccessRule& rule, PassId passId, const ResourceAccess& a, uint32_t shape,
                           const uint32_t* firstSlot, const PassId* producers) {
    const uint32_t write = a.write ? 1u : 0u;
    const bool allowed = ((rule.fineFor >> ((shape % kTransientShape) + write * 2)) & 1u) != 0;
    const bool stagesFit = (a.shaderStages & ~rule.stages) == ShaderStage::None;
    // The version: version 0 is the frame-start content (readable unless
    // transient); a later one needs a producer, not this pass unless it writes
    // over it. An unknown version reads version 0's slot, which has no producer.
    const uint32_t first = firstSlot[a.resource.index];
    const bool known = a.version < firstSlot[a.resource.index + 1] - first;
    const PassId producer = producers[first + (known ? a.version : 0u)];
    const bool produced = producer.valid() & ((producer != passId) | a.write);
    const bool initialFine = (a.version == 0) & (a.write | (shape < kTransientShape));
    return allowed & stagesFit & (initialFine | produced);
  }

  // What checkPasses() reports about one pass, in order (off the common path).
  [[gnu::noinline]] void reportPass(PassId id) {
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
      checkAccess(id, a);
      // Compare with earlier accesses of the same resource in this pass (passes touch few resources).
      for (std::size_t j = 0; j < i; ++j) {
        if (accesses[j].resource == a.resource) checkAccessPair(id, accesses[j], a);
      }
    }
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
    if (deps.forwardOnly ||
        std::all_of(deps.edges.begin(), deps.edges.end(), [](const Dependency& e) { return e.from < e.to; })) {
      return;
    }
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
  const bool outputSized_;  // relative sizes resolve to a non-zero extent when their scales are positive
  std::vector<ValidationError> errors_;
  // Per resource: the last pass naming it (checkPasses()) and shapeOf() its traits.
  struct ResourceFacts {
    uint32_t namedBy;
    uint8_t shape;
  };
  std::vector<ResourceFacts> facts_;
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
