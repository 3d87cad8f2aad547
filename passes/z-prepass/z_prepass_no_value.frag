#version 460
// The z-prepass's own draws when a package adds draws with a colour target
// of their own (render::DepthPassDraws): where one of them keeps the depth,
// the pixel holds no value of the package's.
layout(location = 0) out uint outValue;

void main() { outValue = 0u; }
