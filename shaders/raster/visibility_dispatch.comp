// Visibility pass, between its two passes: the second pass's work groups (VIS_RASTER_GROUP
// invocations, one per covering triangle), as a grid whose rows stay within uMaxGroupsX (workGroupGrid in
// visibility_buffer.cpp, the same rule).
#include "raster/visibility_indirect.glsl"
layout(local_size_x = 1) in;
uniform uint uMaxGroupsX;
void main() {
    uint groups = (coveringCount + uint(VIS_RASTER_GROUP) - 1u) / uint(VIS_RASTER_GROUP);
    uint rows = (groups + uMaxGroupsX - 1u) / uMaxGroupsX;
    dispatchX = rows == 0u ? 0u : (groups + rows - 1u) / rows;
    dispatchY = rows;
    dispatchZ = 1u;
}
