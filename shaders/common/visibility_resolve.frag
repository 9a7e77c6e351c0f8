// Visibility pass, resolve: every covered pixel rebuilds the G-buffer of surface_gbuffer.frag
// from its triangle (perspective-correct barycentrics at the pixel centre) and writes the
// depth the visibility pass kept; background pixels are discarded (they keep the clear).
#include "common/visibility.glsl"
uniform mat4 uView;
uniform vec4 uLayerDepthRow;  // methods::layerDepthRow
layout(location = 0) out vec4 outVelObj;  // xyz: P-space velocity, w: layer depth
layout(location = 1) out vec4 outShade;   // xyz: eye-space normal, w: colour value (overlay)
layout(location = 2) out float outMask;   // texture mask value (overlay)
#ifdef WITH_POSITION
layout(location = 3) out vec4 outPosObj;  // xyz: P-space position
#endif
void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    uint pixel = uint(px.y * uSize.x + px.x);
    uint tri = triangleIds[pixel];
    if (tri == 0xffffffffu) discard;
    uvec3 v = triangleVertices(tri);
    // A vertex as three texels: (position, normal.x), (normal.yz, velocity.xy),
    // (velocity.z, colour value, mask value, -).
    vec4 t[9];
    for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j) t[3 * k + j] = texelFetch(uVertices, int(v[k]) * VERTEX_TEXELS + j);
    // Barycentrics in the window (2D, from the pixel centre), then divided by w.
    vec2 p = gl_FragCoord.xy / vec2(uSize) * 2.0 - 1.0;
    vec4 c0 = uViewProj * vec4(t[0].xyz, 1.0), c1 = uViewProj * vec4(t[3].xyz, 1.0), c2 = uViewProj * vec4(t[6].xyz, 1.0);
    vec2 a = c0.xy / c0.w, b = c1.xy / c1.w, d = c2.xy / c2.w;
    float area = (b.x - a.x) * (d.y - a.y) - (b.y - a.y) * (d.x - a.x);
    vec3 w;
    w.x = ((b.x - p.x) * (d.y - p.y) - (b.y - p.y) * (d.x - p.x)) / area;
    w.y = ((d.x - p.x) * (a.y - p.y) - (d.y - p.y) * (a.x - p.x)) / area;
    w.z = 1.0 - w.x - w.y;
    w /= vec3(c0.w, c1.w, c2.w);
    w /= w.x + w.y + w.z;
    vec4 at0 = w.x * t[0] + w.y * t[3] + w.z * t[6];
    vec4 at1 = w.x * t[1] + w.y * t[4] + w.z * t[7];
    vec4 at2 = w.x * t[2] + w.y * t[5] + w.z * t[8];
    vec3 pos = at0.xyz;
    outVelObj = vec4(at1.zw, at2.x, dot(uLayerDepthRow, vec4(pos, 1.0)));
    outShade = vec4(normalize(mat3(uView) * vec3(at0.w, at1.xy)), at2.y);
    outMask = at2.z;
#ifdef WITH_POSITION
    outPosObj = vec4(pos, 1.0);
#endif
    gl_FragDepth = uintBitsToFloat(depthBits[pixel]);
}
