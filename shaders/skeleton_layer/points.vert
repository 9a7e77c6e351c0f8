// The flow topology layer, critical points: a screen-aligned square per point, dropped
// where the surface hides the point's centre.
#include "skeleton_layer/depth.glsl"
layout(std430, binding = SKELETON_POINTS_BINDING) readonly buffer Points { vec4 point[]; };  // xyz, type
uniform mat4 viewProj;
uniform vec2 viewportPx;
uniform float sizePx;
flat out vec2 centrePx;
flat out int type;

void main() {
    vec4 c = viewProj * vec4(point[gl_InstanceID].xyz, 1.0);
    type = int(point[gl_InstanceID].w + 0.5);
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
    if (c.w <= 0.0) return;
    centrePx = (c.xy / c.w * 0.5 + 0.5) * viewportPx;
    if (hiddenBySurface(centrePx, c.z / c.w * 0.5 + 0.5)) return;
    const vec2 corner[6] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, -1), vec2(1, 1), vec2(-1, 1));
    vec2 px = centrePx + corner[gl_VertexID] * (0.5 * sizePx + 2.0);
    gl_Position = vec4(px / viewportPx * 2.0 - 1.0, 0.0, 1.0);
}
