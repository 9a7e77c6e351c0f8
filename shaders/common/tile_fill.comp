// Screen tiles' merge (methods/common/screen_tiles.h): a layer's tile holds this process's
// own layer, copied over the tile plus guard; here the pixels its piece has no fragment at
// take the layer's background. The pixels other processes sent are written after this,
// merged by depth on the host.
layout(local_size_x = PIXEL_GROUP, local_size_y = PIXEL_GROUP) in;
layout(binding = TILE_FILL_DEPTH_UNIT) uniform sampler2D uDepth;  // this piece's window depth, 1 = background
layout(binding = TILE_FILL_IMAGE_UNIT) writeonly uniform image2D uTile;  // the layer's tile (any float format)
uniform ivec2 uOrigin, uEnd;  // the tile plus guard
uniform vec4 uFill;           // the layer's background, every channel

void main() {
    ivec2 px = uOrigin + ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(px, uEnd))) return;
    if (texelFetch(uDepth, px, 0).r >= 1.0) imageStore(uTile, px, uFill);
}
