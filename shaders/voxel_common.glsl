// Voxel-space helpers shared by the voxel passes (engine/voxel/voxel_grid.hpp is the C++ twin).

uint packCell(uvec3 c) { return c.x | (c.y << 10) | (c.z << 20); }
uvec3 unpackCell(uint p) { return uvec3(p & 1023u, (p >> 10) & 1023u, (p >> 20) & 1023u); }

// Entry i (0..26) of a 3×3×3 block stored x fastest: its coordinates, each 0..2 (a brick's
// samples; less one, the offsets of a node's neighbourhood, brick_gather.glsl).
ivec3 blockCoord3(int i) { return ivec3(i % 3, (i / 3) % 3, i / 9); }

// Opacity is filtered as optical depth, not as α: a voxel of opacity α has optical depth
// τ = −ln(1 − α) per voxel length (α capped at 0.999, τ ≤ 6.9). Linear filtering of a density
// preserves its integral along any line, so a one-voxel wall stays opaque at every coarser level;
// averaging α instead dilutes it by half per level and wide cones see through walls.
const float MAX_OPACITY = 0.999;
float opticalDepth(float alpha) { return -log(1.0 - min(alpha, MAX_OPACITY)); }
// The weight a cell's radiance is stored with, (L·τ, τ): its optical depth, but never 0, so that
// L survives in a cell whose area rounds to α = 0 at 8 bits yet blocks its share of a triangle's
// pixel column (voxelize.frag), a sliver of a triangle crossing cells in depth.
float radianceWeight(float alpha) { return max(opticalDepth(alpha), 1e-6); }
// Opacity of a path of `length` voxels through a medium of density τ per voxel.
float opacityOver(float tau, float length) { return 1.0 - exp(-tau * length); }

// A fragment's column coverage (voxelize.frag): the projection axis (2 bits) and the share of the
// pixel square the triangle covers (6 bits), in one byte.
uint packColumnCoverage(int axis, float coverage) {
    return uint(axis) | (uint(round(clamp(coverage, 0.0, 1.0) * 63.0)) << 2);
}
int columnAxis(uint bits) { return int(bits & 3u); }
float columnCoverage(uint bits) { return float(bits >> 2) / 63.0; }

// Where a fragment's cell lies in its triangle's pixel column (voxelize.frag), in the two bits of
// the fragment's cell word above packCell's 30: whether the triangle also lies in a cell below it
// (lower along the projection axis) and in one above it.
const uint COLUMN_CONTINUES_BELOW = 1u << 30;
const uint COLUMN_CONTINUES_ABOVE = 1u << 31;
const uint CELL_BITS = (1u << 30) - 1u;

// Octahedral encoding of a unit vector into two 16-bit snorm values.
uint packNormal(vec3 n) {
    n /= max(abs(n.x) + abs(n.y) + abs(n.z), 1e-30);
    vec2 e = n.z >= 0.0 ? n.xy : (1.0 - abs(n.yx)) * vec2(n.x >= 0.0 ? 1.0 : -1.0, n.y >= 0.0 ? 1.0 : -1.0);
    return packSnorm2x16(e);
}
vec3 unpackNormal(uint p) {
    vec2 e = unpackSnorm2x16(p);
    vec3 n = vec3(e, 1.0 - abs(e.x) - abs(e.y));
    if (n.z < 0.0) n.xy = (1.0 - abs(n.yx)) * vec2(n.x >= 0.0 ? 1.0 : -1.0, n.y >= 0.0 ? 1.0 : -1.0);
    return normalize(n);
}
