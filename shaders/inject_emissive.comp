#version 450
layout(local_size_x = 64) in;
// inject, emissive part: voxels with emission are touched too, so emissive surfaces light the
// scene through the same radiance filtering with no extra pass.
#include "voxel_common.glsl"
#include "octree.glsl"
#include "radiance_common.glsl"

layout(std430, binding = SSBO_CELL_EMISSIVE) buffer CellEmissive { vec4 cellEmissive[]; };

void main() {
    uint cell = linearInvocation();
    if (cell >= uLevelCount[uLevels]) return;
    vec3 emission = cellEmissive[cell].rgb;
    if (any(greaterThan(emission, vec3(0.0)))) touch(uLevelStart[uLevels] + cell, uLevels);
}
