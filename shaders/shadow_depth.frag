#version 450
// Shadow-map depth (LightViewMap's depth-only draw): the rasterizer writes the depth, and the
// only thing left to the fragment is the alpha test of masked materials, which must cut the same
// holes as in the light-view map. Nothing is written, and opaque materials look nothing up.
#include "material.glsl"

in vec2 vUv;
in vec3 vColor;

void main() {
    if (uAlphaCutoff < 0.0) return;
    materialBaseColor(vUv, vColor);  // discards the texels the mask cuts away
}
