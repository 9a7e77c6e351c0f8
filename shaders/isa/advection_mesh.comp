// ISA stage 2, compute path (isa/advection_mesh.glsl): one invocation per grid vertex
// writes the (R+1)^2 RGBA32F mesh image, or the vertices [uFirst, uEnd) of it.
#include "isa/advection_mesh.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
uniform ivec2 uFirst;  // the first vertex computed
uniform ivec2 uEnd;    // one past the last
layout(binding = MESH_IMAGE_UNIT, rgba32f) writeonly uniform image2D uMesh;  // (R+1)^2 vertices
void main() {
    ivec2 g = uFirst + ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(g, uEnd))) return;
    imageStore(uMesh, g, meshVertex(g));
}
