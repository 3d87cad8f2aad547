#include <shadelgraph/graph/plan_dump.hpp>

#include <sstream>

namespace sg::graph {
namespace {

const std::string& nameOf(const CompiledPlan& plan, ResourceId r) { return plan.resources[r.index].name; }

void writeBarrier(std::ostream& out, const CompiledPlan& plan, const Barrier& b) {
  out << nameOf(plan, b.resource) << ": " << toString(b.srcStages) << "/" << toString(b.srcAccess) << " -> "
      << toString(b.dstStages) << "/" << toString(b.dstAccess);
  if (plan.resources[b.resource.index].desc.type == ResourceType::Image) {
    out << ", " << toString(b.oldLayout) << " -> " << toString(b.newLayout);
  }
  if (b.discard) out << " (discard)";
}

void writeResource(std::ostream& out, const PlannedResource& r) {
  out << "  " << r.name << ": " << toString(r.kind) << ' ';
  if (r.desc.type == ResourceType::Image) {
    const ResolvedImageDesc& d = r.desc.image;
    out << toString(d.format) << ' ' << d.width << 'x' << d.height;
    if (d.depth > 1) out << 'x' << d.depth;
    if (d.layers > 1) out << " layers " << d.layers;
    if (d.mipLevels > 1) out << " mips " << d.mipLevels;
    if (d.samples > 1) out << " samples " << d.samples;
    out << ", usage " << toString(r.desc.imageUsage);
  } else {
    out << r.desc.bufferSize << " bytes, usage " << toString(r.desc.bufferUsage);
  }
  if (r.culled) {
    out << ", unused\n";
    return;
  }
  out << ", queues " << toString(r.desc.queues) << (r.desc.concurrent ? " (concurrent)" : "");
  out << ", used " << r.firstUse << ".." << r.lastUse;
  if (r.memory.placed()) {
    out << ", heap " << r.memory.heap << " @" << r.memory.offset << " +" << r.memory.size;
  }
  out << '\n';
}

}  // namespace

std::string toText(const CompiledPlan& plan) {
  std::ostringstream out;
  out << "order:";
  for (const PassId p : plan.order) out << ' ' << plan.passes[p.index].name;
  out << "\n\nbatches:\n";
  for (uint32_t b = 0; b < plan.batches.size(); ++b) {
    const Batch& batch = plan.batches[b];
    out << "  " << b << " " << toString(batch.queue) << ":";
    for (const PassId p : plan.passesOf(batch)) out << ' ' << plan.passes[p.index].name;
    for (const SemaphoreWait& w : plan.waitsOf(batch)) {
      out << "; wait " << toString(w.queue) << " >= " << w.value << " at " << toString(w.dstStages);
    }
    if (batch.signalValue != 0) out << "; signal " << batch.signalValue;
    out << '\n';
  }
  out << "\npasses:\n";
  for (uint32_t p = 0; p < plan.passes.size(); ++p) {
    const PlannedPass& pass = plan.passes[p];
    out << "  " << pass.name << " (" << toString(pass.queue) << ", " << toString(pass.kind)
        << (pass.sideEffect ? ", side effect" : "") << ")";
    if (pass.culled) {
      out << " culled\n";
      continue;
    }
    out << " batch " << pass.batch << '\n';
    for (const ResourceAccess& a : plan.accessesOf(PassId{p})) {
      out << "    " << (a.write ? "write " : "read  ") << nameOf(plan, a.resource) << " v" << a.version
          << (a.write ? " -> v" + std::to_string(a.version + 1) : "") << ' ' << toString(a.access) << '\n';
    }
    for (const Barrier& b : plan.barriersBefore(PassId{p})) {
      out << "    barrier before ";
      writeBarrier(out, plan, b);
      out << '\n';
    }
    for (const Barrier& b : plan.barriersAfter(PassId{p})) {
      out << "    barrier after ";
      writeBarrier(out, plan, b);
      out << '\n';
    }
  }
  if (!plan.finalBarriers.empty()) {
    out << "\nfinal barriers:\n";
    for (const FinalBarrier& f : plan.finalBarriers) {
      out << "  ";
      writeBarrier(out, plan, f.barrier);
      if (f.afterPass.valid()) out << " (after " << plan.passes[f.afterPass.index].name << ")";
      out << '\n';
    }
  }
  out << "\nresources:\n";
  for (const PlannedResource& r : plan.resources) writeResource(out, r);
  out << "\nmemory: " << plan.heaps.size() << " heap(s), " << plan.heapBytes << " bytes ("
      << plan.heapBytesWithoutAliasing << " without aliasing)" << (plan.memoryEstimated ? ", estimated" : "")
      << '\n';
  return out.str();
}

}  // namespace sg::graph
