// Visibility pass, compute part: one invocation per triangle rasterises it into the
// visibility buffer (visibility.glsl) when it is small and wholly in front of the eye;
// the others are listed for the GL rasteriser (visibility_raster_gl.*), which clips. Edge
// functions are exact integers on vertices snapped to 1/256 pixel, with a top-left rule, so
// two triangles that share an edge cover each pixel centre on it exactly once.
#include "raster/visibility.glsl"
layout(local_size_x = VIS_RASTER_GROUP) in;
// The GL part's DrawElementsIndirectCommand, then the number of triangles deferred (those
// beyond uDeferredCapacity are dropped; the command counts the ones stored), the number of
// covering triangles and the second pass's DispatchIndirectCommand (visibility_dispatch.comp).
#include "raster/visibility_indirect.glsl"
layout(std430, binding = VIS_DEFERRED_BINDING) writeonly buffer Deferred { uint deferredIndices[]; };
layout(std430, binding = VIS_DEFERRED_ID_BINDING) writeonly buffer DeferredIds { uint deferredTriangles[]; };
// The first pass lists the triangles that cover a pixel centre (in depth range); with
// uCompacted the second pass runs over them only: no other triangle can own a pixel.
layout(std430, binding = VIS_COVERING_BINDING) buffer Covering { uint coveringTriangles[]; };
uniform int uCompacted;
uniform uint uTriangleCount;
uniform uint uDeferredCapacity;
uniform int uCullBack;  // skip triangles that turn clockwise in the window

const int kSub = 256;        // subpixel steps per pixel
const int kMaxSide = 32;     // larger triangles go to the GL rasteriser

int edgeAt(ivec2 a, ivec2 b, ivec2 p) { return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x); }
// A pixel centre exactly on an edge counts for one of the two triangles sharing it.
bool ownsTies(ivec2 a, ivec2 b) { return b.y > a.y || (b.y == a.y && b.x < a.x); }

// Which side of the six clip planes a clip-space point is outside of, one bit each.
uint outside(vec4 c) {
    return (c.x < -c.w ? 1u : 0u) | (c.x > c.w ? 2u : 0u) | (c.y < -c.w ? 4u : 0u) | (c.y > c.w ? 8u : 0u) |
           (c.z < -c.w ? 16u : 0u) | (c.z > c.w ? 32u : 0u);
}

void main() {
    // A 2D grid of work groups when the triangles need more than the first dimension allows.
    uint index = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationIndex;
    if (index >= (uPass == 1 && uCompacted != 0 ? coveringCount : uTriangleCount)) return;
    uint tri = uPass == 1 && uCompacted != 0 ? coveringTriangles[index] : index;
    uvec3 v = triangleVertices(tri);
    vec4 c[3];
    bool deferred = false;
    uint out0 = 0xffffffffu;
    for (int k = 0; k < 3; ++k) {
        c[k] = uViewProj * vec4(vertexPosition(v[k]), 1.0);
        out0 &= outside(c[k]);
        // Behind or near the eye plane, or far outside the image: the GL rasteriser clips.
        deferred = deferred || !(c[k].w > 1e-6 * abs(c[k].z)) || any(greaterThan(abs(c[k].xy), vec2(4.0 * c[k].w)));
    }
    if (out0 != 0u) return;  // wholly outside one clip plane: nothing to draw
    ivec2 s[3];
    vec2 w[3];  // window coordinates, pixels
    float z[3];
    for (int k = 0; k < 3; ++k) {
        vec3 ndc = c[k].xyz / c[k].w;
        w[k] = (ndc.xy * 0.5 + 0.5) * vec2(uSize);
        s[k] = ivec2(round(w[k] * float(kSub)));
        z[k] = ndc.z * 0.5 + 0.5;
    }
    // Depth is the plane through the unsnapped vertices (as GL interpolates it), so that
    // snapping moves coverage by 1/256 pixel at most but never the depth of a pixel.
    vec2 e1 = w[1] - w[0], e2 = w[2] - w[0];
    float areaF = e1.x * e2.y - e2.x * e1.y;
    vec2 dz = vec2((z[1] - z[0]) * e2.y - (z[2] - z[0]) * e1.y, (z[2] - z[0]) * e1.x - (z[1] - z[0]) * e2.x) / areaF;
    ivec2 lo = min(min(s[0], s[1]), s[2]), hi = max(max(s[0], s[1]), s[2]);
    deferred = deferred || any(greaterThan(hi - lo, ivec2(kMaxSide * kSub)));
    if (deferred) {
        if (uPass == 0) {
            uint slot = atomicAdd(deferredCount, 1u);
            if (slot < uDeferredCapacity) {
                atomicAdd(drawCount, 3u);
                deferredIndices[3u * slot] = v[0];
                deferredIndices[3u * slot + 1u] = v[1];
                deferredIndices[3u * slot + 2u] = v[2];
                deferredTriangles[slot] = tri;
            }
        }
        return;
    }
    int area = edgeAt(s[0], s[1], s[2]);
    if (area == 0 || (uCullBack != 0 && area < 0)) return;
    if (area < 0) {  // two-sided: turn it counter-clockwise (the depth plane is symmetric)
        ivec2 ts = s[1]; s[1] = s[2]; s[2] = ts;
        area = -area;
    }
    // Pixels whose centres (x + 0.5) lie in the box, clipped to the image.
    ivec2 first = max(ivec2(ceil((vec2(lo) - float(kSub / 2)) / float(kSub))), ivec2(0));
    ivec2 last = min(ivec2(floor((vec2(hi) - float(kSub / 2)) / float(kSub))), uSize - 1);
    bool t0 = ownsTies(s[1], s[2]), t1 = ownsTies(s[2], s[0]), t2 = ownsTies(s[0], s[1]);
    // One loop over the box's pixels (not two nested): the lanes of a SIMD batch then run
    // as many iterations as the largest box has pixels, not its width times its height.
    int count = (last.x - first.x + 1) * (last.y - first.y + 1);
    int x = first.x, y = first.y;
    bool covers = false;
    for (int i = 0; i < count; ++i, ++x) {
        if (x > last.x) {
            x = first.x;
            ++y;
        }
        ivec2 p = ivec2(x, y) * kSub + kSub / 2;
        int e0 = edgeAt(s[1], s[2], p), e1 = edgeAt(s[2], s[0], p), e2 = edgeAt(s[0], s[1], p);
        bool inside = (e0 > 0 || (e0 == 0 && t0)) && (e1 > 0 || (e1 == 0 && t1)) && (e2 > 0 || (e2 == 0 && t2));
        precise float depth = z[0] + dot(dz, vec2(x, y) + 0.5 - w[0]);
        if (inside && depth >= 0.0 && depth <= 1.0) {
            visit(uint(y * uSize.x + x), depth, tri);
            covers = true;
        }
    }
    if (uPass == 0 && covers) coveringTriangles[atomicAdd(coveringCount, 1u)] = tri;
}
