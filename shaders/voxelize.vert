#version 450
// Voxelization, vertex stage: scene-local positions to voxel space.
#include "material_vertex.glsl"

uniform vec3 uVoxelOrigin;  // scene-local position of voxel (0,0,0)
uniform float uVoxelScale;  // voxels per scene-local unit

out vec3 vVoxel;
out vec2 vUv;     // the base-colour texture's coordinates (set and transform applied)
out vec3 vColor;  // vertex colour

void main() {
    vVoxel = (inPosition - uVoxelOrigin) * uVoxelScale;
    vUv = materialUv();
    vColor = inColor;
}
