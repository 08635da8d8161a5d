#version 450
// Shared vertex stage of every pass that rasterizes the scene from some view.
#include "material_vertex.glsl"

uniform mat4 uViewProjection;

out vec3 vPosition;
out vec3 vNormal;
out vec2 vUv;     // the base-colour texture's coordinates (set and transform applied)
out vec3 vColor;  // vertex colour

void main() {
    vPosition = inPosition;
    vNormal = inNormal;
    vUv = materialUv();
    vColor = inColor;
    gl_Position = uViewProjection * vec4(inPosition, 1.0);
}
