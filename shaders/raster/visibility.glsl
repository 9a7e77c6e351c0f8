// The surface as a visibility buffer (raster/visibility_buffer.h): per pixel the depth
// and the id of the nearest triangle, kept with 32-bit atomics in two passes (pass 0: the
// least depth; pass 1: the least triangle id among those at that depth, so that the result
// does not depend on the order the triangles run in). Shared by the compute pass (small
// triangles) and the GL pass (the triangles sent back to the GL rasteriser).
layout(binding = VIS_VERTEX_UNIT) uniform samplerBuffer uVertices;    // SurfaceGpu's vertices, VERTEX_TEXELS a vertex
layout(binding = VIS_TRIANGLE_UNIT) uniform usamplerBuffer uTriangles;  // SurfaceGpu's triangles, one a texel
layout(std430, binding = VIS_DEPTH_BINDING) coherent buffer Depth { uint depthBits[]; };  // float bits; ~0u: none
layout(std430, binding = VIS_ID_BINDING) coherent buffer Ids { uint triangleIds[]; };   // ~0u: none
uniform mat4 uViewProj;
uniform ivec2 uSize;  // image size in pixels
uniform int uPass;    // 0: least depth; 1: least triangle id at that depth

uvec3 triangleVertices(uint tri) { return texelFetch(uTriangles, int(tri)).xyz; }
// The position starts a texel (gpu_bindings.h asserts it): one fetch.
vec3 vertexPosition(uint v) { return texelFetch(uVertices, int(v) * VERTEX_TEXELS + SURFACE_POS_OBJ_OFFSET / 4).xyz; }
// Float `i` (a SURFACE_*_OFFSET) of a vertex held as its texels, and the three from `i` on.
float vertexFloat(vec4 t[VERTEX_TEXELS], int i) { return t[i / 4][i % 4]; }
vec3 vertexVec3(vec4 t[VERTEX_TEXELS], int i) { return vec3(vertexFloat(t, i), vertexFloat(t, i + 1), vertexFloat(t, i + 2)); }
// A vertex as its texels (the layout of gpu_bindings.h's surface_vertex), for the resolves.
void vertexTexels(uint v, out vec4 t[VERTEX_TEXELS]) {
    for (int j = 0; j < VERTEX_TEXELS; ++j) t[j] = texelFetch(uVertices, int(v) * VERTEX_TEXELS + j);
}
// The resolves' barycentrics of the point `pNdc` (a pixel centre) in the triangle of clip
// positions c0, c1, c2: in the window (2D, what GL's noperspective interpolates with) and
// then divided by w (perspective-correct, GL's default smooth).
vec3 windowBarycentrics(vec2 pNdc, vec4 c0, vec4 c1, vec4 c2) {
    vec2 a = c0.xy / c0.w, b = c1.xy / c1.w, d = c2.xy / c2.w;
    float area = (b.x - a.x) * (d.y - a.y) - (b.y - a.y) * (d.x - a.x);
    vec3 w;
    w.x = ((b.x - pNdc.x) * (d.y - pNdc.y) - (b.y - pNdc.y) * (d.x - pNdc.x)) / area;
    w.y = ((d.x - pNdc.x) * (a.y - pNdc.y) - (d.y - pNdc.y) * (a.x - pNdc.x)) / area;
    w.z = 1.0 - w.x - w.y;
    return w;
}
vec3 perspectiveBarycentrics(vec3 window, vec4 c0, vec4 c1, vec4 c2) {
    vec3 w = window / vec3(c0.w, c1.w, c2.w);
    return w / (w.x + w.y + w.z);
}

// One covered pixel of triangle `tri` at window depth `depth` (the same float in both
// passes: the same code computes it from the same inputs).
void visit(uint pixel, float depth, uint tri) {
    uint bits = floatBitsToUint(depth);
    if (uPass == 0) atomicMin(depthBits[pixel], bits);
    else if (depthBits[pixel] == bits) atomicMin(triangleIds[pixel], tri);
}
