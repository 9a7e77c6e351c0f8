// w = 1 marks the surface, as in the steady velocity image (common/surface_gbuffer.frag).
in vec3 vVel;
layout(location = 0) out vec4 outVel;
void main() { outVel = vec4(vVel, 1.0); }
