// Vertex-stage half of the material lookup (material.glsl is the fragment half), set by
// GpuScene::draw() for every draw range: which texture-coordinate set the base-colour texture
// reads and its KHR_texture_transform (scene/texture_mapping.hpp). The transform is affine, so
// applying it per vertex and interpolating gives exactly the per-fragment result.
layout(location = 0) in vec3 inPosition;  // scene-local
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;
layout(location = 3) in vec2 inUv1;
layout(location = 4) in vec3 inColor;     // linear vertex colour, multiplies the base colour

uniform int uTexCoordSet;   // 0: inUv, 1: inUv1
uniform mat3 uUvTransform;  // identity without KHR_texture_transform

vec2 materialUv() { return (uUvTransform * vec3(uTexCoordSet == 1 ? inUv1 : inUv, 1.0)).xy; }
