// Layer "detail-level": one hue per detail level (sgDetailLevel: the shadel's
// level decoupled; forward, the level a 1024-shadel chart would use).
#include <framework/render/shaders/debug_color.glsl>

vec4 detailLevelColor(Surface s) { return vec4(sgLevelColor(sgDetailLevel()), 1.0); }
