// IBFVS stages 1-3 from the visibility buffer (--surface-raster compute): per covered pixel,
// what polygon_advection.vert/.frag give the nearest fragment there, from its triangle:
// t = T(x_i - v_i dt) per vertex [L eq. 13] interpolated linearly in the window
// (noperspective, [L §IV-J]), shade and mask perspective-correct, the visibility pass's depth.
// ADVECT_IN_COMPUTE as in polygon_advection.frag. Background pixels keep the clear.
#include "raster/visibility.glsl"
#include "ibfvs/mesh_projection.glsl"
#include "ibfvs/polygon_advection.glsl"
uniform mat4 uPrevViewProj;
uniform mat4 uView;
uniform float uDt;
layout(location = FLOW_OUT) out vec4 outFlow;  // ADVECT_IN_COMPUTE: RG32F texture coordinate
layout(location = SHADE_OUT) out vec4 outShade;
layout(location = MASK_OUT) out float outMask;
void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    uint pixel = uint(px.y * uSize.x + px.x);
    uint tri = triangleIds[pixel];
    if (tri == 0xffffffffu) discard;
    uvec3 v = triangleVertices(tri);
    vec4 t[3][VERTEX_TEXELS];
    vec4 c[3];
    vec2 texcoord[3];
    for (int k = 0; k < 3; ++k) {
        vertexTexels(v[k], t[k]);
        vec3 posObj = vertexVec3(t[k], SURFACE_POS_OBJ_OFFSET);
        c[k] = uViewProj * vec4(posObj, 1.0);
        texcoord[k] = pathlineTexcoord(posObj, vertexVec3(t[k], SURFACE_VEL_OBJ_OFFSET), uDt, uPrevViewProj);
    }
    vec2 p = gl_FragCoord.xy / vec2(uSize) * 2.0 - 1.0;
    vec3 ws = windowBarycentrics(p, c[0], c[1], c[2]);
    vec3 wp = perspectiveBarycentrics(ws, c[0], c[1], c[2]);
    vec2 tc = ws.x * texcoord[0] + ws.y * texcoord[1] + ws.z * texcoord[2];
    if (min(min(c[0].w, c[1].w), c[2].w) <= 0.0) {
        // A vertex behind the eye has no projection, so neither its t nor a window-space
        // interpolation exists (the GL draw clips and interpolates garbage there): eq. 13 at
        // the pixel's own surface point instead.
        vec3 posObj = wp.x * vertexVec3(t[0], SURFACE_POS_OBJ_OFFSET) + wp.y * vertexVec3(t[1], SURFACE_POS_OBJ_OFFSET) +
                      wp.z * vertexVec3(t[2], SURFACE_POS_OBJ_OFFSET);
        vec3 velObj = wp.x * vertexVec3(t[0], SURFACE_VEL_OBJ_OFFSET) + wp.y * vertexVec3(t[1], SURFACE_VEL_OBJ_OFFSET) +
                      wp.z * vertexVec3(t[2], SURFACE_VEL_OBJ_OFFSET);
        tc = pathlineTexcoord(posObj, velObj, uDt, uPrevViewProj);
    }
#ifdef ADVECT_IN_COMPUTE
    outFlow = vec4(tc, 0.0, 1.0);
#else
    outFlow = vec4(polygonAdvectedFlow(gl_FragCoord.xy, tc), 0.0, 0.0, 1.0);
#endif
    vec3 normalObj = wp.x * vertexVec3(t[0], SURFACE_NORMAL_OBJ_OFFSET) + wp.y * vertexVec3(t[1], SURFACE_NORMAL_OBJ_OFFSET) +
                     wp.z * vertexVec3(t[2], SURFACE_NORMAL_OBJ_OFFSET);
    vec3 color = vec3(vertexFloat(t[0], SURFACE_COLOR_OFFSET), vertexFloat(t[1], SURFACE_COLOR_OFFSET),
                      vertexFloat(t[2], SURFACE_COLOR_OFFSET));
    vec3 mask = vec3(vertexFloat(t[0], SURFACE_MASK_OFFSET), vertexFloat(t[1], SURFACE_MASK_OFFSET),
                     vertexFloat(t[2], SURFACE_MASK_OFFSET));
    outShade = vec4(normalize(mat3(uView) * normalObj), dot(wp, color));
    outMask = dot(wp, mask);
    gl_FragDepth = uintBitsToFloat(depthBits[pixel]);
}
