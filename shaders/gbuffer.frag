#version 450
// Deferred G-buffer: what the lighting passes need to know about the visible surface per pixel.
#include "material.glsl"

in vec3 vPosition;
in vec3 vNormal;
in vec2 vUv;
in vec3 vColor;

uniform vec3 uEye;  // scene-local

layout(location = 0) out vec4 outAlbedo;    // linear albedo, 1
layout(location = 1) out vec4 outNormal;    // unit normal facing the camera, 0
layout(location = 2) out vec4 outPosition;  // scene-local position, 1 (0 = sky)
layout(location = 3) out vec4 outEmissive;  // emitted radiance, 0
layout(location = 4) out vec4 outGeometricNormal;  // the triangle's unit normal facing the camera, 0

void main() {
    vec4 base = materialBaseColorOverPixel(vUv, vColor);
    outAlbedo = vec4(base.rgb, 1.0);
    vec3 geometric = facingGeometricNormal(vPosition, uEye - vPosition);
    outNormal = vec4(facingNormal(vNormal, geometric), 0.0);
    outGeometricNormal = vec4(geometric, 0.0);
    outPosition = vec4(vPosition, 1.0);
    outEmissive = vec4(uEmissive, 0.0);
}
