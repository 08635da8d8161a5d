#version 450
layout(local_size_x = 64) in;
// inject, last step: per touched voxel, the area-average outgoing radiance of its surface,
//   L = Σ ρ·Φ / (π · A) + L_emitted      (A: the voxel's surface area in scene units²),
// stored weighted by the voxel's optical depth τ (voxel_common.glsl): (L·τ, τ), the form the
// brick filters and the cone tracer use. Unlit parts of the surface count as
// dark because A is the whole surface inside the voxel, lit or not.
#define WORK_LIST_TOUCHED
#include "voxel_common.glsl"
#include "octree.glsl"
#include "radiance_common.glsl"
#include "work_list.glsl"

layout(std430, binding = 7) buffer CellAlbedo { uint cellAlbedo[]; };
layout(std430, binding = 9) buffer CellArea { float cellArea[]; };
layout(std430, binding = 11) buffer CellEmissive { vec4 cellEmissive[]; };

uniform float uFluxScale;
uniform float uVoxelArea;   // one voxel face in scene units²
uniform int uHasEmissive;

void main() {
    bool valid;
    uint node = workNode(valid);
    if (!valid) return;
    uint cell = node - uLevelStart[uLevels];
    vec3 flux;
    for (uint c = 0u; c < 3u; ++c) {
        uint index = cell * 6u + 2u * c;
        flux[c] = float((double(radianceAccumulator[index]) + 4294967296.0lf * double(radianceAccumulator[index + 1u])) /
                        double(uFluxScale));
    }
    float area = cellArea[cell] * uVoxelArea;
    vec3 radiance = area > 0.0 ? flux / (3.14159265358979 * area) : vec3(0.0);
    if (uHasEmissive != 0) {
        radiance += cellEmissive[cell].rgb;
    }
    float tau = opticalDepth(unpackUnorm4x8(cellAlbedo[cell]).a);
    cellRadiance[cell] = vec4(radiance * tau, tau);
}
