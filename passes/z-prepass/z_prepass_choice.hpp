#pragma once
// The per-renderer state behind ZPrepass::Auto: overdraw measured once and
// the pre-pass decided from it (z_prepass_rule.hpp) frame after frame. A
// measurement frame draws the pre-pass (what frames did before there was a
// measurement) with occlusion queries around it and forward-opaque; its
// counts arrive a frame or more later, without waiting. It is measured again
// when it goes stale (overdrawStale: new size, visible set or camera), not
// per frame: counting costs nothing, but only a frame with the pre-pass can
// count the overdraw it removes, so measuring every frame would mean the
// pre-pass every frame.
#include <memory>
#include <optional>
#include <string>

#include "overdraw_probe.hpp"
#include "z_prepass_rule.hpp"

namespace sg::gpu {
class Context;
}

namespace sg::passes {

// What `render --stats` reports of the last frame's choice.
struct ZPrepassReport {
  bool drawn = false;      // the last frame drew the pre-pass
  bool measuring = false;  // the last frame was a measurement frame (or waits for one's counts)
  std::string reason;      // why drawn or not
  std::optional<Overdraw> measured;
  uint64_t measuredFrame = 0;  // the frame whose counts `measured` holds
  uint32_t measurements = 0;   // measurement frames whose counts arrived
};

class ZPrepassChoice {
 public:
  struct Frame {
    bool prepass = true;
    OverdrawProbe* probe = nullptr;  // set in a measurement frame: count with it
  };
  // The Auto decision for frame `frameNumber`, drawing `view`.
  Frame decide(gpu::Context& context, const OverdrawView& view, uint64_t frameNumber);
  // The decision of a frame that did not ask (forced, or decoupled objects visible).
  void recordForced(bool drawn, std::string reason);
  const ZPrepassReport& report() const { return report_; }
  // The report with the counts of a measurement frame that has completed since the last decision.
  const ZPrepassReport& collectedReport() {
    collect();
    return report_;
  }
  // The probe when frame `frameNumber` is a measurement frame (forward-opaque counts with it too).
  OverdrawProbe* probeFor(uint64_t frameNumber) const {
    return pending_ && pendingFrame_ == frameNumber ? probe_.get() : nullptr;
  }

 private:
  void collect();

  std::unique_ptr<OverdrawProbe> probe_;
  bool pending_ = false;  // a measurement frame's counts are awaited
  OverdrawView pendingView_, measuredView_;
  uint64_t pendingFrame_ = 0;
  ZPrepassReport report_;
};

// The key the forward package keeps it under (FrameContext::ownState), for
// the app to read its report (Renderer::findState).
inline constexpr const char* kZPrepassChoiceState = "z-prepass.choice";

}  // namespace sg::passes
