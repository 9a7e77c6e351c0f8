// Visibility pass, resolve: every covered pixel rebuilds the G-buffer of surface_gbuffer.frag
// from its triangle (perspective-correct barycentrics at the pixel centre) and writes the
// depth the visibility pass kept; background pixels are discarded (they keep the clear).
#include "common/visibility.glsl"
uniform mat4 uView;
uniform vec4 uLayerDepthRow;  // methods::layerDepthRow
layout(location = VEL_OBJ_OUT) out vec4 outVelObj;  // xyz: P-space velocity, w: layer depth
layout(location = SHADE_OUT) out vec4 outShade;     // xyz: eye-space normal, w: colour value (overlay)
layout(location = MASK_OUT) out float outMask;      // texture mask value (overlay)
#ifdef WITH_POSITION
layout(location = POS_OBJ_OUT) out vec4 outPosObj;  // xyz: P-space position
#endif
void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    uint pixel = uint(px.y * uSize.x + px.x);
    uint tri = triangleIds[pixel];
    if (tri == 0xffffffffu) discard;
    uvec3 v = triangleVertices(tri);
    // Each vertex as its texels (the layout of gpu_bindings.h's surface_vertex).
    vec4 t[3][VERTEX_TEXELS];
    for (int k = 0; k < 3; ++k)
        for (int j = 0; j < VERTEX_TEXELS; ++j) t[k][j] = texelFetch(uVertices, int(v[k]) * VERTEX_TEXELS + j);
    // Barycentrics in the window (2D, from the pixel centre), then divided by w.
    vec2 p = gl_FragCoord.xy / vec2(uSize) * 2.0 - 1.0;
    vec4 c0 = uViewProj * vec4(vertexVec3(t[0], SURFACE_POS_OBJ_OFFSET), 1.0);
    vec4 c1 = uViewProj * vec4(vertexVec3(t[1], SURFACE_POS_OBJ_OFFSET), 1.0);
    vec4 c2 = uViewProj * vec4(vertexVec3(t[2], SURFACE_POS_OBJ_OFFSET), 1.0);
    vec2 a = c0.xy / c0.w, b = c1.xy / c1.w, d = c2.xy / c2.w;
    float area = (b.x - a.x) * (d.y - a.y) - (b.y - a.y) * (d.x - a.x);
    vec3 w;
    w.x = ((b.x - p.x) * (d.y - p.y) - (b.y - p.y) * (d.x - p.x)) / area;
    w.y = ((d.x - p.x) * (a.y - p.y) - (d.y - p.y) * (a.x - p.x)) / area;
    w.z = 1.0 - w.x - w.y;
    w /= vec3(c0.w, c1.w, c2.w);
    w /= w.x + w.y + w.z;
    vec4 at[VERTEX_TEXELS];
    for (int j = 0; j < VERTEX_TEXELS; ++j) at[j] = w.x * t[0][j] + w.y * t[1][j] + w.z * t[2][j];
    vec3 pos = vertexVec3(at, SURFACE_POS_OBJ_OFFSET);
    outVelObj = vec4(vertexVec3(at, SURFACE_VEL_OBJ_OFFSET), dot(uLayerDepthRow, vec4(pos, 1.0)));
    outShade = vec4(normalize(mat3(uView) * vertexVec3(at, SURFACE_NORMAL_OBJ_OFFSET)), vertexFloat(at, SURFACE_COLOR_OFFSET));
    outMask = vertexFloat(at, SURFACE_MASK_OFFSET);
#ifdef WITH_POSITION
    outPosObj = vec4(pos, 1.0);
#endif
    gl_FragDepth = uintBitsToFloat(depthBits[pixel]);
}
