// w: the depth of the visible layer, as in the steady velocity image
// (raster/surface_gbuffer.frag, methods::layerDepthRow); 0 on the background.
in vec3 vVel;
in float vLayerDepth;
layout(location = LEVEL_VELOCITY_OUT) out vec4 outVel;
void main() { outVel = vec4(vVel, vLayerDepth); }
