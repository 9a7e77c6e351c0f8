// ISA stage 2, fragment path (isa/advection_mesh.glsl): one full-screen triangle over the
// (R+1)^2 RGBA32F mesh image, one fragment per grid vertex.
#include "isa/advection_mesh.glsl"
out vec4 outMesh;
void main() { outMesh = meshVertex(ivec2(gl_FragCoord.xy)); }
