#pragma once
// CPU reference voxelizer: the ground truth the GPU voxelizer is tested against (the GPU's
// occupied-cell set must contain this one). Simple, exhaustive and in double precision; speed
// only matters as far as the tests go (Cornell box at 128³ in a fraction of a second).
//
// Semantics. Cell c is the CLOSED unit cube [c, c+1]³ of voxel space (engine/voxel/voxel_grid.hpp)
// and a triangle is the closed convex hull of its three vertices. A cell is occupied iff the two
// intersect, so a triangle lying exactly on the plane z = 3 occupies the cells of both layers
// z = 2 and z = 3, and a vertex exactly on a cell corner occupies all 8 cells around it.
// Degenerate triangles (a segment, a point) are voxelized as the segment or point.
//
// Precision. All arithmetic is in double. The results are exact whenever the products in the
// separating-axis test are exact (e.g. coordinates that are small dyadic rationals, as in the
// tests); for arbitrary inputs a configuration that touches a cell to within ~1e-16 relative
// may go either way.
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.hpp"
#include "voxel/voxel_grid.hpp"

namespace vct::reference {

// The first of the 13 Akenine-Möller candidate axes (3 box axes, the triangle normal, the 9
// products edge × box axis, in that order) on which the triangle and the closed box
// [centre − halfSize, centre + halfSize] project to disjoint intervals; nullopt if there is none,
// i.e. they overlap. Zero axes (normal of a degenerate triangle, zero edges, edges parallel to a
// box axis) project everything onto 0 and never separate, which makes the same 13 axes complete
// for segments (3 box axes + 3 direction × box axis) and points (3 box axes).
std::optional<glm::dvec3> findSeparatingAxis(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c, glm::dvec3 boxCentre,
                                             glm::dvec3 boxHalfSize);

// True iff the closed triangle abc and the closed box share at least one point.
bool triangleOverlapsBox(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c, glm::dvec3 boxCentre, glm::dvec3 boxHalfSize);

// Every cell [x,x+1]×[y,y+1]×[z,z+1], 0 ≤ x,y,z < 2^levels, that the triangle (voxel-space
// vertices) overlaps; packed with packCell, sorted ascending. Only the cells of the triangle's
// bounding box (clamped to the grid) are tested: the others are separated by a box axis anyway.
// A triangle with a non-finite coordinate yields no cells.
std::vector<std::uint32_t> voxelizeTriangle(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c, int levels);

// All cells overlapped by any triangle of the scene (vertices mapped with grid.toVoxel in double),
// sorted and unique.
std::vector<std::uint32_t> voxelizeScene(const Scene& scene, const VoxelGrid& grid);

}  // namespace vct::reference
