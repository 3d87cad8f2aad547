#version 460
// The nearest object's id (the depth test keeps it).
layout(location = 0) flat in uint inId;
layout(location = 0) out uint outId;

void main() { outId = inId; }
