// One render of the surface into per-pixel buffers: ISA's velocity image [L §IV-C.1] and
// the hybrid method's seed textures [W §4]. Per-vertex attributes interpolated over each
// triangle (Gouraud); only the nearest layer survives the z-test.
layout(location = SURFACE_POS_OBJ_LOCATION) in vec3 aPosObj;
layout(location = SURFACE_NORMAL_OBJ_LOCATION) in vec3 aNormalObj;
layout(location = SURFACE_VEL_OBJ_LOCATION) in vec3 aVelObj;
layout(location = SURFACE_COLOR_LOCATION) in float aColor;  // colour value, 0..1 over the colour range (NaN: none)
layout(location = SURFACE_MASK_LOCATION) in float aMask;    // texture mask value, 0..1
uniform mat4 uViewProj;
uniform mat4 uView;
uniform vec4 uLayerDepthRow;  // methods::layerDepthRow
out vec3 vPosObj;
out vec3 vVelObj;
out vec3 vNormalEye;
out float vColor;
out float vMask;
out float vLayerDepth;  // 1 + eye depth as a fraction of the depth range
void main() {
    vPosObj = aPosObj;
    vVelObj = aVelObj;
    vNormalEye = mat3(uView) * aNormalObj;
    vColor = aColor;
    vMask = aMask;
    vLayerDepth = dot(uLayerDepthRow, vec4(aPosObj, 1.0));
    gl_Position = uViewProj * vec4(aPosObj, 1.0);
}
