#version 450
layout(local_size_x = 64) in;
// svo_leaves, step 1: every fragment adds its values to its cell's integer accumulators
// (DESIGN 5.2). Integer addition is associative, so the sums — and everything built from them —
// are bit-identical whatever the order in which thousands of fragments of one cell arrive.
//   albedo: 8-bit channels summed in 32 bits (exact up to 16.8 M fragments per cell)
//   normal: components × 127 summed as two's-complement 32-bit integers
//   column partners: the bits of cellColumns (svo_leaves_normalize), or-ed
//   area, emission, and (in uProjectedArea) the area projected along x, y, z, apart for the faces
//   facing +a and −a (area·|n_a|, on the side n_a points to; along the axis the triangle was
//   projected on, the coverage of its column, voxelize.frag): 64-bit fixed point (low word, then a
//   carry into the high word)
#include "voxel_common.glsl"
#include "octree.glsl"

layout(rgba32ui, binding = IMAGE_FRAGMENTS) uniform readonly uimageBuffer uFragments;
layout(r32ui, binding = IMAGE_FRAGMENT_NODE) uniform readonly uimageBuffer uFragmentNode;  // the fragment's cell node
layout(std430, binding = SSBO_MATERIALS) buffer Materials { vec4 materials[]; };  // {baseColor, emissive} per material
layout(r32ui, binding = IMAGE_CELL_ACCUMULATORS) uniform uimageBuffer uAccumulators;  // CELL_ACCUMULATOR_FIELDS per cell
layout(r32ui, binding = IMAGE_PROJECTED_AREA) uniform uimageBuffer uProjectedArea;  // PROJECTED_AREA_FIELDS per cell: +x −x +y −y +z −z, 64-bit each

uniform uint uFragmentCount;
uniform int uHasEmissive;
uniform float uEmissiveScale;  // fixed-point units per unit of radiance

const float AREA_SCALE = 16777216.0;  // 2^24 units per voxel face

void add64(int base, uint value) {
    uint old = imageAtomicAdd(uAccumulators, base, value);
    if (old + value < old) imageAtomicAdd(uAccumulators, base + 1, 1u);
}

void main() {
    uint f = linearInvocation();
    if (f >= uFragmentCount) return;
    uvec4 fragment = imageLoad(uFragments, int(f));
    uint cell = imageLoad(uFragmentNode, int(f)).x - uLevelStart[uLevels];
    int base = int(cell) * CELL_ACCUMULATOR_FIELDS;
    uint material = fragment.w >> 16;
    float area = unpackHalf2x16(fragment.w & 0xFFFFu).x;
    vec3 albedo = clamp(unpackUnorm4x8(fragment.y).rgb * materials[2u * material].rgb, 0.0, 1.0);
    uvec3 albedo8 = uvec3(round(albedo * 255.0));
    ivec3 normal = ivec3(round(unpackNormal(fragment.z) * 127.0));
    imageAtomicAdd(uAccumulators, base + 0, 1u);
    imageAtomicAdd(uAccumulators, base + 1, albedo8.r);
    imageAtomicAdd(uAccumulators, base + 2, albedo8.g);
    imageAtomicAdd(uAccumulators, base + 3, albedo8.b);
    imageAtomicAdd(uAccumulators, base + 4, uint(normal.x));
    imageAtomicAdd(uAccumulators, base + 5, uint(normal.y));
    imageAtomicAdd(uAccumulators, base + 6, uint(normal.z));
    add64(base + 7, uint(round(area * AREA_SCALE)));
    vec3 faceNormal = unpackNormal(fragment.z);
    vec3 projected = area * abs(faceNormal);
    uint column = fragment.y >> 24;
    projected[columnAxis(column)] = max(projected[columnAxis(column)], columnCoverage(column));
    if (columnCoverage(column) > 0.0) {
        // The cells beside this one along the projection axis that hold the same triangle's column.
        uint bits = 0u;
        if ((fragment.x & COLUMN_CONTINUES_BELOW) != 0u) bits |= 1u << (2 * columnAxis(column));
        if ((fragment.x & COLUMN_CONTINUES_ABOVE) != 0u) bits |= 2u << (2 * columnAxis(column));
        if (bits != 0u) imageAtomicOr(uAccumulators, base + 15, bits);
    }
    for (int c = 0; c < 3; ++c) {
        uint value = uint(round(projected[c] * AREA_SCALE));
        if (value == 0u) continue;
        int index = int(cell) * PROJECTED_AREA_FIELDS + 4 * c + (faceNormal[c] < 0.0 ? 2 : 0);
        uint old = imageAtomicAdd(uProjectedArea, index, value);
        if (old + value < old) imageAtomicAdd(uProjectedArea, index + 1, 1u);
    }
    if (uHasEmissive != 0) {
        vec3 emission = materials[2u * material + 1u].rgb;
        for (int c = 0; c < 3; ++c) add64(base + 9 + 2 * c, uint(round(max(emission[c], 0.0) * uEmissiveScale)));
    }
}
