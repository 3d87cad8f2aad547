#include "z_prepass_choice.hpp"

#include <cstdio>

namespace sg::passes {

void ZPrepassChoice::collect() {
  if (!pending_) return;
  if (!probe_->recorded()) {  // the frame was only planned, not drawn: measure again
    pending_ = false;
    return;
  }
  const auto counts = probe_->read();
  if (!counts) return;
  pending_ = false;
  report_.measured = Overdraw{pendingView_.triangles, counts->prepass, counts->forwardOpaque,
                              pendingView_.texturesPerTriangle};
  report_.measuredFrame = pendingFrame_;
  ++report_.measurements;
  measuredView_ = pendingView_;
}

ZPrepassChoice::Frame ZPrepassChoice::decide(gpu::Context& context, const OverdrawView& view, uint64_t frameNumber) {
  collect();
  report_.drawn = true;
  report_.measuring = true;
  if (pending_) {
    report_.reason = "overdraw being measured (its frame still running)";
    return {};
  }
  if (!report_.measured || overdrawStale(measuredView_, view)) {
    if (!probe_) probe_ = std::make_unique<OverdrawProbe>(context);
    probe_->arm();
    pending_ = true;
    pendingView_ = view;
    pendingFrame_ = frameNumber;
    report_.reason = "measuring overdraw (drawn with the pre-pass)";
    return {.prepass = true, .probe = probe_.get()};
  }
  const Overdraw& o = *report_.measured;
  report_.measuring = false;
  report_.drawn = zPrepassPays(o);
  char why[200];
  std::snprintf(why, sizeof why,
                "%.2f overdrawn fragments a triangle at %.2f textures a triangle %s (pays above %.2f untextured; "
                "depth complexity %.2f)",
                o.triangles ? double(o.overdrawn()) / double(o.triangles) : 0.0, o.texturesPerTriangle,
                report_.drawn ? "pays" : "does not pay", kZPrepassFragmentsPerTriangle, o.depthComplexity());
  report_.reason = why;
  return {.prepass = report_.drawn};
}

void ZPrepassChoice::recordForced(bool drawn, std::string reason) {
  report_.drawn = drawn;
  report_.measuring = false;
  report_.reason = std::move(reason);
}

}  // namespace sg::passes
