// Visibility buffer, occlusion between pieces (VisibilityBuffer::dropOccluded).
// uStep 0: one invocation per screen cell of VIS_OCCLUDER_CELL² pixels in [uOrigin, uEnd)
// (cells): the cell's farthest depth bits, none (~0u: beyond every depth's bits) where a
// pixel of it is uncovered or outside uFootprint.
// uStep 1: one invocation per pixel of [uOrigin, uEnd) (pixels): the pixel is dropped (depth
// and id none) where its depth is strictly beyond its cell's occluder (the group's least
// farthest depth; its bits compare as the floats do, depths being in [0, 1]).
#include "raster/visibility.glsl"
layout(local_size_x = PIXEL_GROUP, local_size_y = PIXEL_GROUP) in;
layout(std430, binding = VIS_OCCLUDER_BINDING) buffer Occluders { uint occluderBits[]; };
uniform int uStep;
uniform ivec2 uOrigin;     // the cells (step 0) or pixels (step 1) run: [uOrigin, uEnd)
uniform ivec2 uEnd;
uniform ivec4 uFootprint;  // the pixels this frame's raster cleared and can cover; others may be stale
uniform int uCellsX;
void main() {
    ivec2 at = uOrigin + ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(at, uEnd))) return;
    if (uStep == 0) {
        ivec2 from = at * VIS_OCCLUDER_CELL, to = min(from + VIS_OCCLUDER_CELL, uSize);
        uint farthest = 0u;
        if (any(lessThan(from, uFootprint.xy)) || any(greaterThan(to, uFootprint.zw))) farthest = 0xffffffffu;
        for (int y = from.y; y < to.y && farthest != 0xffffffffu; ++y)
            for (int x = from.x; x < to.x; ++x) farthest = max(farthest, depthBits[y * uSize.x + x]);
        occluderBits[at.y * uCellsX + at.x] = farthest;
        return;
    }
    uint pixel = uint(at.y * uSize.x + at.x);
    uint bits = depthBits[pixel];
    if (bits != 0xffffffffu && bits > occluderBits[(at.y / VIS_OCCLUDER_CELL) * uCellsX + at.x / VIS_OCCLUDER_CELL]) {
        depthBits[pixel] = 0xffffffffu;
        triangleIds[pixel] = 0xffffffffu;
    }
}
