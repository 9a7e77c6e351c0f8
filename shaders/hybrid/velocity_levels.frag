// w: the eye depth of the visible layer, as in the steady velocity image
// (common/surface_gbuffer.frag); 0 on the background.
in vec3 vVel;
in float vEyeDepth;
layout(location = 0) out vec4 outVel;
void main() { outVel = vec4(vVel, vEyeDepth); }
