#include "synthetic_graph.hpp"

#include <algorithm>
#include <random>

namespace sg::graph {
namespace {

Access readAccess(const SyntheticResource& r) { return r.image ? Access::Sampled : Access::StorageRead; }

Access writeAccess(const SyntheticResource& r, PassKind kind) {
  return r.image && kind == PassKind::Raster ? Access::ColorAttachment : Access::StorageWrite;
}

}  // namespace

SyntheticGraph makeSyntheticGraph(uint32_t passCount, uint32_t seed) {
  std::mt19937 rng(seed);
  const auto chance = [&](double p) { return std::uniform_real_distribution<double>(0.0, 1.0)(rng) < p; };
  const auto below = [&](uint32_t n) { return std::uniform_int_distribution<uint32_t>(0, n - 1)(rng); };

  SyntheticGraph recipe;
  std::vector<uint32_t> written;  // resources some earlier pass wrote, in write order
  const auto newResource = [&] {
    SyntheticResource r;
    r.name = "r" + std::to_string(recipe.resources.size());
    r.image = chance(0.6);
    r.imageDesc = ImageDesc{.format = chance(0.5) ? Format::RGBA16F : Format::RGBA8Unorm,
                            .size = Size::relative(chance(0.7) ? 1.0f : 0.5f)};
    r.bufferDesc = BufferDesc{.size = 4096u << below(8)};
    recipe.resources.push_back(r);
    return static_cast<uint32_t>(recipe.resources.size() - 1);
  };

  for (uint32_t p = 0; p + 1 < passCount; ++p) {
    SyntheticPass pass;
    pass.name = "p" + std::to_string(p);
    if (chance(0.2)) {
      pass.queue = QueueClass::AsyncCompute;
      pass.kind = PassKind::Compute;
    } else if (chance(0.15)) {
      pass.kind = PassKind::Compute;
    }
    const uint32_t readCount = written.empty() ? 0 : 1 + below(3);
    for (uint32_t i = 0; i < readCount; ++i) {
      const auto recent = static_cast<uint32_t>(std::min<std::size_t>(written.size(), 8));
      const uint32_t r = chance(0.1) ? written[below(static_cast<uint32_t>(written.size()))]
                                     : written[written.size() - 1 - below(recent)];
      if (std::find(pass.reads.begin(), pass.reads.end(), r) == pass.reads.end()) pass.reads.push_back(r);
    }
    const uint32_t writeCount = 1 + below(2);
    for (uint32_t i = 0; i < writeCount; ++i) {
      uint32_t r = newResource();
      if (!written.empty() && chance(0.3)) {  // a new version of something already written
        const uint32_t existing = written[written.size() - 1 - below(static_cast<uint32_t>(
                                                                  std::min<std::size_t>(written.size(), 8)))];
        const bool read = std::find(pass.reads.begin(), pass.reads.end(), existing) != pass.reads.end();
        const bool twice = std::find(pass.writes.begin(), pass.writes.end(), existing) != pass.writes.end();
        if (!read && !twice) {
          recipe.resources.pop_back();
          r = existing;
        }
      }
      pass.writes.push_back(r);
      written.push_back(r);
    }
    recipe.passes.push_back(pass);
  }

  // The output: imported, written by a last graphics pass reading the latest result.
  SyntheticResource output{.name = "output", .image = true, .imageDesc = ImageDesc{.size = Size::relative(1.0f)}};
  recipe.resources.push_back(output);
  SyntheticPass last{.name = "present", .reads = {}, .writes = {static_cast<uint32_t>(recipe.resources.size() - 1)}};
  if (!written.empty()) last.reads.push_back(written.back());
  recipe.passes.push_back(last);
  return recipe;
}

void declare(RenderGraph& g, const SyntheticGraph& recipe) {
  std::vector<ResourceHandle> current;
  current.reserve(recipe.resources.size());
  for (std::size_t r = 0; r + 1 < recipe.resources.size(); ++r) {
    const SyntheticResource& res = recipe.resources[r];
    current.push_back(res.image ? g.createImage(res.name, res.imageDesc) : g.createBuffer(res.name, res.bufferDesc));
  }
  const SyntheticResource& out = recipe.resources.back();
  current.push_back(g.importImage(out.name, out.imageDesc, ImportedState{},
                                  FinalState{Layout::TransferSrc, PipelineStage::Transfer, AccessFlag::TransferRead}));

  for (const SyntheticPass& p : recipe.passes) {
    Pass& pass = g.addPass(p.name, p.queue, p.kind);
    for (const uint32_t r : p.reads) pass.read(current[r], readAccess(recipe.resources[r]));
    for (const uint32_t r : p.writes) current[r] = pass.write(current[r], writeAccess(recipe.resources[r], p.kind));
    pass.execute([](sg::PassContext&) {});
  }
  g.markOutput(current.back());
}

CompileOptions syntheticCompileOptions() {
  CompileOptions options;
  options.outputWidth = 1920;
  options.outputHeight = 1080;
  return options;
}

}  // namespace sg::graph
