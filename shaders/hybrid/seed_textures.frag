// 32-bit float positions, as [W §6] found necessary; w = 1 marks the surface.
in vec3 vPosObj;
in vec3 vVelObj;
in vec3 vNormalEye;
in float vSpeed;
layout(location = 0) out vec4 outPosObj;
layout(location = 1) out vec4 outVelObj;
layout(location = 2) out vec4 outShade;  // eye normal, true speed (overlay)
void main() {
    outPosObj = vec4(vPosObj, 1.0);
    outVelObj = vec4(vVelObj, 1.0);
    outShade = vec4(normalize(vNormalEye), vSpeed);
}
