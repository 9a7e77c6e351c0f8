// ISA stage 1, velocity image [L §IV-C.1]: the mesh with its 3D velocity as a
// per-vertex attribute, interpolated over each triangle (Gouraud).
layout(location = 0) in vec3 aPosObj;
layout(location = 1) in vec3 aNormalObj;
layout(location = 2) in vec3 aVelObj;
layout(location = 3) in float aSpeed;  // true speed, for the colour map
uniform mat4 uViewProj;
uniform mat4 uView;
out vec3 vVelObj;
out vec3 vNormalEye;
out float vSpeed;
void main() {
    vVelObj = aVelObj;
    vSpeed = aSpeed;
    vNormalEye = mat3(uView) * aNormalObj;
    gl_Position = uViewProj * vec4(aPosObj, 1.0);
}
