// The flow topology layer, lines: each piece an instance, a screen-space quad around it
// of the line's half width plus one pixel for the anti-aliased edge.
#include "skeleton_layer/depth.glsl"
layout(std430, binding = SKELETON_SEGMENTS_BINDING) readonly buffer Segments { vec4 segment[]; };  // a.xyz kind, b.xyz
uniform mat4 viewProj;
uniform vec2 viewportPx;
uniform float halfWidthPx;
flat out vec2 aPx, bPx;
flat out float depthA, depthB, kind;
flat out int depthTest;  // 0: both ends in front of the surface, no per-pixel test

void main() {
    vec4 a = viewProj * vec4(segment[2 * gl_InstanceID].xyz, 1.0);
    vec4 b = viewProj * vec4(segment[2 * gl_InstanceID + 1].xyz, 1.0);
    kind = segment[2 * gl_InstanceID].w;
    if (a.w <= 0.0 || b.w <= 0.0) { gl_Position = vec4(2.0, 2.0, 2.0, 1.0); return; }  // behind the eye
    aPx = (a.xy / a.w * 0.5 + 0.5) * viewportPx;
    bPx = (b.xy / b.w * 0.5 + 0.5) * viewportPx;
    depthA = a.z / a.w * 0.5 + 0.5;
    depthB = b.z / b.w * 0.5 + 0.5;
    bool hiddenA = hiddenBySurface(aPx, depthA), hiddenB = hiddenBySurface(bPx, depthB);
    if (hiddenA && hiddenB) { gl_Position = vec4(2.0, 2.0, 2.0, 1.0); return; }  // behind the surface
    depthTest = hiddenA || hiddenB ? 1 : 0;
    vec2 along = bPx - aPx;
    along = length(along) > 1e-6 ? normalize(along) : vec2(1.0, 0.0);
    vec2 across = vec2(-along.y, along.x);
    const vec2 corner[6] = vec2[](vec2(0, -1), vec2(1, -1), vec2(1, 1), vec2(0, -1), vec2(1, 1), vec2(0, 1));
    vec2 c = corner[gl_VertexID];
    float r = halfWidthPx + 1.0;
    vec2 px = mix(aPx, bPx, c.x) + along * (c.x * 2.0 - 1.0) * r + across * c.y * r;
    gl_Position = vec4(px / viewportPx * 2.0 - 1.0, 0.0, 1.0);
}
