// Float targets: no 8-bit quantisation of the velocity (the papers' limitation).
in vec3 vVelObj;
in vec3 vNormalEye;
in float vSpeed;
layout(location = 0) out vec4 outVelObj;  // xyz: P-space velocity, w: 1 on the surface
layout(location = 1) out vec4 outShade;   // xyz: eye-space normal, w: speed (for the overlay)
void main() {
    outVelObj = vec4(vVelObj, 1.0);
    outShade = vec4(normalize(vNormalEye), vSpeed);
}
