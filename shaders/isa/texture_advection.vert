// ISA stage 3, texture advection [L §IV-D.1]: the R x R grid at its image positions,
// textured with the previous F_a at the backward-integrated coordinates.
layout(location = 0) in vec4 aMeshVertex;  // texcoord xy, edge flag z
uniform int uGridRes;
out vec2 vTexcoord;
out float vEdge;
void main() {
    ivec2 g = ivec2(gl_VertexID % (uGridRes + 1), gl_VertexID / (uGridRes + 1));
    vec2 posNdc = vec2(g) / float(uGridRes) * 2.0 - 1.0;
    vTexcoord = aMeshVertex.xy;
    vEdge = aMeshVertex.z;
    gl_Position = vec4(posNdc, 0.0, 1.0);
}
