#version 460
// shadel-mark's bilinear requests (SG_MARK_REQUESTS: the depth pre-pass
// writes each pixel's mask slot and box instead of an atomic setting the
// bits) turned into mask bits: a thread per 4x4 pixels ORs the boxes of the
// requests with the same slot and sets them with one atomic per distinct
// slot. The loop runs as often as the thread with the most distinct slots
// needs (usually one or two: shadels are about a pixel or larger). Only the
// rectangle the decoupled draws can cover is dispatched (push constants): on
// lavapipe a compute shader pays for empty pixels too.
#include <framework/shadel/shaders/decoupled.glsl>
#include <passes/shadel-mark/shadel_box.glsl>

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = kBindShadelMasks, std430) buffer ShadelMasks { uint64_t shadelMasks[]; };
layout(set = 0, binding = kBindMarkRequests, r32ui) uniform readonly uimage2D requests;
layout(push_constant) uniform Rect { ivec2 rectOrigin; ivec2 rectEnd; };  // pixels, end exclusive

void main() {
  ivec2 first = rectOrigin + ivec2(gl_GlobalInvocationID.xy) * 4;
  uint pending[16];
  for (int i = 0; i < 16; ++i) {
    ivec2 p = first + ivec2(i & 3, i >> 2);
    pending[i] = all(lessThan(p, rectEnd)) ? imageLoad(requests, p).x : 0u;
  }
  for (;;) {
    uint request = 0u;
    for (int i = 0; i < 16; ++i) request = request != 0u ? request : pending[i];
    if (request == 0u) break;
    uint slot = sgRequestSlot(request);
    uint64_t bits = uint64_t(0);
    for (int i = 0; i < 16; ++i) {
      bool same = pending[i] != 0u && sgRequestSlot(pending[i]) == slot;
      bits |= same ? sgRequestBits(pending[i]) : uint64_t(0);
      pending[i] = same ? 0u : pending[i];
    }
    atomicOr(shadelMasks[slot], bits);
  }
}
