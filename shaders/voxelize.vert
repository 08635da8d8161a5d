#version 450
// Voxelization, vertex stage: scene-local positions to voxel space.
layout(location = 0) in vec3 inPosition;
layout(location = 2) in vec2 inUv;

uniform vec3 uVoxelOrigin;  // scene-local position of voxel (0,0,0)
uniform float uVoxelScale;  // voxels per scene-local unit

out vec3 vVoxel;
out vec2 vUv;

void main() {
    vVoxel = (inPosition - uVoxelOrigin) * uVoxelScale;
    vUv = inUv;
}
