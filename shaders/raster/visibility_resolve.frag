// Visibility pass, resolve: every covered pixel rebuilds the G-buffer of surface_gbuffer.frag
// from its triangle (perspective-correct barycentrics at the pixel centre) and writes the
// depth the visibility pass kept; background pixels are discarded (they keep the clear).
#include "raster/visibility.glsl"
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
    vec4 t[3][VERTEX_TEXELS];
    for (int k = 0; k < 3; ++k) vertexTexels(v[k], t[k]);
    vec4 c0 = uViewProj * vec4(vertexVec3(t[0], SURFACE_POS_OBJ_OFFSET), 1.0);
    vec4 c1 = uViewProj * vec4(vertexVec3(t[1], SURFACE_POS_OBJ_OFFSET), 1.0);
    vec4 c2 = uViewProj * vec4(vertexVec3(t[2], SURFACE_POS_OBJ_OFFSET), 1.0);
    vec2 p = gl_FragCoord.xy / vec2(uSize) * 2.0 - 1.0;
    vec3 w = perspectiveBarycentrics(windowBarycentrics(p, c0, c1, c2), c0, c1, c2);
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
