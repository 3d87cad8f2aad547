#version 460
// Edges where the depth buffer's Laplacian is large against the remaining
// depth range (perspective depth crowds near 1, so the test is relative).
layout(set = 0, binding = 0) uniform sampler2D depth;
layout(push_constant) uniform Constants { float strength; float threshold; } pc;
layout(location = 0) in vec2 inUv;
layout(location = 0) out vec4 outColor;

void main() {
  const ivec2 p = ivec2(gl_FragCoord.xy);
  const ivec2 size = textureSize(depth, 0) - 1;
  const float c = texelFetch(depth, p, 0).r;
  const float l = texelFetch(depth, clamp(p + ivec2(-1, 0), ivec2(0), size), 0).r;
  const float r = texelFetch(depth, clamp(p + ivec2(1, 0), ivec2(0), size), 0).r;
  const float u = texelFetch(depth, clamp(p + ivec2(0, -1), ivec2(0), size), 0).r;
  const float d = texelFetch(depth, clamp(p + ivec2(0, 1), ivec2(0), size), 0).r;
  const float laplacian = abs(4.0 * c - l - r - u - d);
  const float scale = max(1.0 - min(min(c, l), min(r, min(u, d))), 1e-6);
  const float edge = smoothstep(pc.threshold, 2.0 * pc.threshold, laplacian / scale);
  const float a = pc.strength * edge;
  outColor = vec4(vec3(0.0) * a, a);  // premultiplied black, "over"
}
