#version 450
layout(local_size_x = 64) in;
// svo_leaves, step 2: per cell, turn the integer sums into values: mean albedo, opacity
// α = min(1, area in voxel-face units), mean normal, area, mean emission (brick_layout.hpp), and
// the opacity by axis from the projected areas.
#include "voxel_common.glsl"
#include "octree.glsl"

layout(r32ui, binding = IMAGE_CELL_ACCUMULATORS) uniform readonly uimageBuffer uAccumulators;
layout(r32ui, binding = IMAGE_PROJECTED_AREA) uniform readonly uimageBuffer uProjectedArea;  // PROJECTED_AREA_FIELDS per cell
layout(std430, binding = SSBO_LEAF_STATUS) buffer Status { uint overflowCells; uint maxFragmentsInCell; };
layout(std430, binding = SSBO_CELL_VALUES) buffer CellAlbedo { uint cellAlbedo[]; };    // RGBA8: albedo, opacity
layout(std430, binding = SSBO_CELL_NORMAL) buffer CellNormal { uint cellNormal[]; };    // octahedral
layout(std430, binding = SSBO_CELL_AREA) buffer CellArea { float cellArea[]; };       // voxel-face units
layout(std430, binding = SSBO_CELL_FRAGMENTS) buffer CellFragments { uint cellFragments[]; };
// Bit 2a: a triangle of the cell crosses into the cell below it along a, in depth of its
// projection (voxelize.frag); bit 2a + 1: into the cell above. radiance_normalize pools the
// photons of such cells.
layout(std430, binding = SSBO_CELL_COLUMNS) buffer CellColumns { uint cellColumns[]; };
// Float, not half: emission may be anything from 1e-9 to 1e9 W/(m²·sr) (half floats flushed dim
// emission to 0 and turned bright emission into Inf).
layout(std430, binding = SSBO_CELL_EMISSIVE) buffer CellEmissive { vec4 cellEmissive[]; };  // RGB, 0
// Opacity by direction (octree.hpp): a floor blocks a ray crossing it, not one running along it.
layout(std430, binding = SSBO_CELL_OPACITY) buffer CellOpacity { uint cellOpacity[]; };  // RGBA8 (αx, αy, αz, α)

uniform int uHasEmissive;
uniform float uEmissiveScale;

const double AREA_SCALE = 16777216.0;
const uint MAX_EXACT_FRAGMENTS = 16843009u;  // 255 · n < 2^32

double load64(int base) {
    return double(imageLoad(uAccumulators, base).x) + 4294967296.0lf * double(imageLoad(uAccumulators, base + 1).x);
}

void main() {
    uint cell = linearInvocation();
    if (cell >= uLevelCount[uLevels]) return;
    int base = int(cell) * CELL_ACCUMULATOR_FIELDS;
    uint count = imageLoad(uAccumulators, base).x;
    if (count > MAX_EXACT_FRAGMENTS) atomicAdd(overflowCells, 1u);
    atomicMax(maxFragmentsInCell, count);
    float n = float(max(count, 1u));
    vec3 albedo = vec3(imageLoad(uAccumulators, base + 1).x, imageLoad(uAccumulators, base + 2).x,
                       imageLoad(uAccumulators, base + 3).x) / (255.0 * n);
    vec3 normal = vec3(int(imageLoad(uAccumulators, base + 4).x), int(imageLoad(uAccumulators, base + 5).x),
                       int(imageLoad(uAccumulators, base + 6).x));
    float area = float(load64(base + 7) / AREA_SCALE);
    cellAlbedo[cell] = packUnorm4x8(vec4(albedo, min(area, 1.0)));
    cellNormal[cell] = packNormal(dot(normal, normal) > 0.0 ? normalize(normal) : vec3(0.0, 0.0, 1.0));
    cellArea[cell] = area;
    // Along each axis, the larger of the areas facing its two ways: a closed object's faces
    // towards +a and towards −a each cover its silhouette, and their sum would count a rod, a
    // baluster or a chain link twice as opaque as it is; a sheet open on both sides covers with
    // its one side.
    vec3 projected;
    for (int c = 0; c < 3; ++c) {
        double facing[2];
        for (int side = 0; side < 2; ++side) {
            int index = int(cell) * PROJECTED_AREA_FIELDS + 4 * c + 2 * side;
            facing[side] = (double(imageLoad(uProjectedArea, index).x) +
                            4294967296.0lf * double(imageLoad(uProjectedArea, index + 1).x)) / AREA_SCALE;
        }
        projected[c] = float(max(facing[0], facing[1]));
    }
    cellOpacity[cell] = packUnorm4x8(vec4(min(projected, vec3(1.0)), min(area, 1.0)));
    cellFragments[cell] = count;
    cellColumns[cell] = imageLoad(uAccumulators, base + 15).x;
    if (uHasEmissive != 0) {
        vec3 emission = vec3(float(load64(base + 9)), float(load64(base + 11)), float(load64(base + 13))) /
                        (uEmissiveScale * n);
        cellEmissive[cell] = vec4(emission, 0.0);
    }
}
