#pragma once
// shadelgraph bench --effects: what each effect the scene may call for costs,
// forward and decoupled, and what it adds to the image.
//   shadows: a set under the same lights of one type (directional: 4 suns of
//     4 cascades, spot: 4, point: 2 of 6 cube faces: the 16-map atlas's
//     limit), 0, 1, 2, ... of them shadowed; cost per shadowed light against
//     the same scene unshadowed, ꟻLIP of the unshadowed frame against the
//     all-shadowed one;
//   lights: N ranged point lights, the light-cull pass forced on (threshold 0)
//     against brute force (threshold above N), ꟻLIP between them (~0);
//   ibl: an environment image against the analytic sky, the one-time
//     prefilter (first frames of fresh renderers) apart from the per-frame cost;
//   bloom: on against off (its threshold out of reach).
// Each comparison's configurations render alternately frame by frame in one
// run (one warm-up round, then --repetitions timed rounds); medians of the
// GPU frame time and per pass. Manual exposure (an EV100 per scene), so an
// effect changes the image only by what it adds. Writes effects.json.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <shadelgraph/gpu/context.hpp>
#include <shadelgraph/gpu/device.hpp>

namespace sg::app {

struct EffectsBenchArgs {
  std::vector<std::string> groups;  // which comparisons run: shadows, lights, ibl, bloom
  std::vector<std::string> sizes;
  int repetitions = 3;
  std::vector<int> lightCounts;
};

void runEffectsBench(gpu::Context& context, gpu::Device& device, const EffectsBenchArgs& args,
                     const std::filesystem::path& out);

}  // namespace sg::app
