#version 450
// Shadow-map depth of masked materials (LightViewMap's depth-only draw; opaque materials are
// drawn with no fragment shader at all): the rasterizer writes the depth, and the only thing left
// to the fragment is the alpha test, which must cut the same holes as in the light-view map.
#include "material.glsl"

in vec2 vUv;
in vec3 vColor;

void main() {
    materialBaseColor(vUv, vColor);  // discards the texels the mask cuts away
}
