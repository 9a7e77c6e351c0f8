// The flow topology layer, lines: each piece a screen-space quad of the outline's half width
// plus one pixel for the anti-aliased edge, four corners (two triangles by index) of one
// draw. Inside a line a piece ends on the bisector of the join with its neighbour (a miter),
// so consecutive pieces meet edge to edge and no pixel is drawn twice; at a line's ends it
// reaches one half width further for the round cap. The pieces are those SkeletonLayer kept
// for the view (line_simplify.h), prev and next its kept neighbours. Cost: on llvmpipe mostly
// the set-up of each piece's two triangles, not their pixels (doc/bench/topology.md).
#include "skeleton_layer/depth.glsl"
// Per piece: the point before a (w 1: it exists), a (w: kind), b, the point after b (w 1: exists).
layout(std430, binding = SKELETON_SEGMENTS_BINDING) readonly buffer Segments { vec4 segment[]; };
uniform mat4 viewProj;
uniform vec2 viewportPx;
uniform float halfWidthPx;  // the outline's
flat out vec2 aPx, bPx;
flat out float depthA, depthB, kind;
flat out int depthTest;  // 0: both ends in front of the surface, no per-pixel test
flat out int caps;       // bit 0: round cap at a, bit 1: at b

vec2 toPx(vec4 c) { return (c.xy / c.w * 0.5 + 0.5) * viewportPx; }

// The offset from an end of the piece to its quad's side: across the piece, or along the
// join's bisector where the line goes on (lengthened to keep the half width, at most 2x).
vec2 sideAt(vec2 across, vec2 along, bool joined, vec2 neighbourAlong) {
    if (!joined) return across;
    vec2 miter = vec2(-(along + neighbourAlong).y, (along + neighbourAlong).x);
    float m = length(miter);
    if (m < 1e-3) return across;
    miter /= m;
    return miter / max(dot(miter, across), 0.5);
}

void main() {
    const int piece = gl_VertexID / 4, corner = gl_VertexID % 4;  // a -, b -, b +, a +
    vec4 prev = segment[4 * piece], a4 = segment[4 * piece + 1], b4 = segment[4 * piece + 2], next = segment[4 * piece + 3];
    vec4 a = viewProj * vec4(a4.xyz, 1.0), b = viewProj * vec4(b4.xyz, 1.0);
    vec4 p = viewProj * vec4(prev.xyz, 1.0), n = viewProj * vec4(next.xyz, 1.0);
    kind = a4.w;
    if (a.w <= 0.0 || b.w <= 0.0) { gl_Position = vec4(2.0, 2.0, 2.0, 1.0); return; }  // behind the eye
    aPx = toPx(a);
    bPx = toPx(b);
    depthA = a.z / a.w * 0.5 + 0.5;
    depthB = b.z / b.w * 0.5 + 0.5;
    // the ends speak for the piece's inside: a simplified piece keeps the depth of the line it
    // stands for within 0.2 % (line_simplify.h), so its ends are hidden where the line's are
    bool hiddenA = hiddenBySurface(aPx, depthA), hiddenB = hiddenBySurface(bPx, depthB);
    if (hiddenA && hiddenB) { gl_Position = vec4(2.0, 2.0, 2.0, 1.0); return; }  // behind the surface
    depthTest = hiddenA || hiddenB ? 1 : 0;
    vec2 along = bPx - aPx;
    float len = length(along);
    along = len > 1e-6 ? along / len : vec2(1.0, 0.0);
    vec2 across = vec2(-along.y, along.x);
    // a neighbour joins where it exists, is in front of the eye and not on top of the end
    vec2 toA = p.w > 0.0 ? aPx - toPx(p) : vec2(0.0), fromB = n.w > 0.0 ? toPx(n) - bPx : vec2(0.0);
    bool joinA = prev.w > 0.5 && p.w > 0.0 && length(toA) > 1e-3 && len > 1e-6;
    bool joinB = next.w > 0.5 && n.w > 0.0 && length(fromB) > 1e-3 && len > 1e-6;
    caps = (joinA ? 0 : 1) | (joinB ? 0 : 2);
    float r = halfWidthPx + 1.0;
    bool atB = corner == 1 || corner == 2;
    float side = corner < 2 ? -1.0 : 1.0;
    vec2 end = atB ? bPx : aPx;
    bool joined = atB ? joinB : joinA;
    vec2 offset = atB ? sideAt(across, along, joinB, normalize(fromB + vec2(1e-9)))
                      : sideAt(across, along, joinA, normalize(toA + vec2(1e-9)));
    vec2 px = end + (joined ? vec2(0.0) : along * (atB ? r : -r)) + offset * side * r;
    gl_Position = vec4(px / viewportPx * 2.0 - 1.0, 0.0, 1.0);
}
