// IBFVS edge mask: the outline quads other processes captured (edge_mask.geom), drawn as the
// two triangles of each strip, (0, 1, 2) and (2, 1, 3).
layout(std430, binding = EDGE_CAPTURE_BINDING) readonly buffer Shared {
    vec4 quads[];  // 4 corners per quad
};
void main() {
    const int corner[6] = int[6](0, 1, 2, 2, 1, 3);
    gl_Position = quads[4 * (gl_VertexID / 6) + corner[gl_VertexID % 6]];
}
