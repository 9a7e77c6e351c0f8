// ISA stage 2, compute path (isa/advection_mesh.glsl): one invocation per grid vertex
// writes the (R+1)^2 RGBA32F mesh image.
#include "isa/advection_mesh.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = MESH_IMAGE_UNIT, rgba32f) writeonly uniform image2D uMesh;  // (R+1)^2 vertices
void main() {
    ivec2 g = ivec2(gl_GlobalInvocationID.xy);
    if (g.x > uGridRes || g.y > uGridRes) return;
    imageStore(uMesh, g, meshVertex(g));
}
