// ISA stage 3, texture advection, per-pixel variant: one full-screen triangle; each
// pixel interpolates the advection mesh bilinearly (the hardware's texture filter)
// instead of the rasteriser interpolating it over the grid's triangles.
layout(binding = 1) uniform sampler2D uMesh;  // (R+1)^2, linear filtering
uniform int uGridRes;
out vec2 vGridUv;
void main() {
    vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
    // Image [0,1] -> texel centres of the (R+1)^2 vertex texture.
    vGridUv = (p * float(uGridRes) + 0.5) / float(uGridRes + 1);
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
