// Overlay [L eq. 10], fragment path: one full-screen triangle into the composite.
#include "present/overlay.glsl"
out vec4 outColor;
void main() { outColor = vec4(overlayColor(ivec2(gl_FragCoord.xy)), 1.0); }
