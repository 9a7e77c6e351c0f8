// Visibility pass, GL part (visibility_raster_gl.vert): no colour output, only the atomics.
#include "raster/visibility.glsl"
layout(std430, binding = VIS_DEFERRED_ID_BINDING) readonly buffer DeferredIds { uint deferredTriangles[]; };
void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    visit(uint(px.y * uSize.x + px.x), gl_FragCoord.z, deferredTriangles[gl_PrimitiveID]);
}
