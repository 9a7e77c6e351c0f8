// Float targets: no 8-bit quantisation of the velocity (the papers' limitation); 32-bit
// positions where the hybrid method needs them [W §6]. The velocity's w holds the depth of
// the visible layer (methods::layerDepthRow; 0: background), so the hybrid's particles
// check that they are still on that layer with the same lookup that gives their velocity.
in vec3 vPosObj;
in vec3 vVelObj;
in vec3 vNormalEye;
in float vColor;
in float vMask;
in float vLayerDepth;
layout(location = VEL_OBJ_OUT) out vec4 outVelObj;  // xyz: P-space velocity, w: layer depth
layout(location = SHADE_OUT) out vec4 outShade;     // xyz: eye-space normal, w: colour value (overlay)
layout(location = MASK_OUT) out float outMask;      // texture mask value (overlay)
#ifdef WITH_POSITION
layout(location = POS_OBJ_OUT) out vec4 outPosObj;  // xyz: P-space position
#endif
void main() {
    outVelObj = vec4(vVelObj, vLayerDepth);
    outShade = vec4(normalize(vNormalEye), vColor);
    outMask = vMask;
#ifdef WITH_POSITION
    outPosObj = vec4(vPosObj, 1.0);
#endif
}
