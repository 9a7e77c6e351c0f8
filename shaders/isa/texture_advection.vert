// ISA stage 3, texture advection [L §IV-D.1], mesh variant: the R x R grid at its image
// positions, textured with the previous F_a at the backward-integrated coordinates.
layout(binding = ISA_MESH_UNIT) uniform sampler2D uMesh;  // (R+1)^2: texcoord xy, edge flag z
uniform int uGridRes;
out vec2 vTexcoord;
out float vEdge;
void main() {
    ivec2 g = ivec2(gl_VertexID % (uGridRes + 1), gl_VertexID / (uGridRes + 1));
    vec4 m = texelFetch(uMesh, g, 0);
    vTexcoord = m.xy;
    vEdge = m.z;
    gl_Position = vec4(vec2(g) / float(uGridRes) * 2.0 - 1.0, 0.0, 1.0);
}
