// ParaView plugin: the method's image into ParaView's framebuffer by depth
// (src/paraview/representation/vtkFlowSurfMapper.cxx). Drawn over the renderer's
// viewport with depth test LEQUAL against ParaView's depth, so what lies in front of the
// surface keeps its colour. Blend overlay: multiplied onto ParaView's colour (the blend
// state does it); the other overlays replace it.
layout(binding = 0) uniform sampler2D uImage;  // the method's composite, RGBA8
layout(binding = 1) uniform sampler2D uDepth;  // the method's surface depth, 1 = background
uniform ivec2 uOrigin;                         // the viewport's lower-left pixel
uniform float uDepthBias;                      // window depth: rounding between VTK's and our matrices
out vec4 outColor;

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy) - uOrigin;
    float depth = texelFetch(uDepth, px, 0).r;
    if (depth >= 1.0) discard;
    outColor = vec4(texelFetch(uImage, px, 0).rgb, 1.0);
    gl_FragDepth = max(depth - uDepthBias, 0.0);
}
