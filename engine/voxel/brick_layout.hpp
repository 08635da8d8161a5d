#pragma once
// What a brick sample means (DESIGN 5.4). The GPU passes (bricks.cpp, bricks_mip.cpp) and the
// CPU reference in tests/reference/ both implement exactly these definitions.
//
// Cells and values. The finest voxels ("cells") are unit cubes [c, c+1)³ of voxel space. An
// occupied cell has albedo ρ (mean of its fragments) and opacity α = min(1, A) where A is the
// surface area inside it in voxel-face units (a plane straight through a cell has A = 1). Bricks
// filter its optical depth τ = −ln(1 − min(α, 0.999)) (per voxel length), not α: a density
// filtered linearly keeps its integral along any line, so a one-voxel wall stays opaque at every
// level (averaging α would halve it per level). The value is weighted by τ: V(c) = (ρ·τ, τ);
// the radiance pool holds (L·τ, τ). Empty cells have V = 0.
//
// Lattice. Level l has nodes of edge e_l = 2^(L−l) voxels and a sample lattice of spacing
// h_l = e_l / 2: a node's 3×3×3 brick holds the samples at its corners, edge midpoints, face
// centres and centre, sample (i,j,k) ∈ {0,1,2}³ at node.min + (i,j,k)·h_l. Samples on a face,
// edge or corner are shared with the neighbouring nodes.
//
// Partial bricks P_n: what node n alone contributes to its samples.
//   Leaf level (l = L−1, h = 1):  P_n(q) = 1/8 · Σ V(c) over the cells c inside n whose closed
//       cube contains q  (the box filter of the 8 cells around a lattice point).
//   Parents (l < L−1, h):  P_n(Q) = Σ over children c of n, Σ over d ∈ {−1,0,1}³ with
//       Q + d·h/2 inside c's closed cube:  w(d) · P_c(Q + d·h/2),
//       w(d) = Π over axes (d = 0 ? 1/2 : 1/4)  (the ¼ ½ ¼ tent per axis).
//   A child sample shared by several children is counted once per child, each with its own
//   partial value: the partials of shared samples add up to the whole (this is the
//   "multiplicity" weighting of DESIGN 5.4, done exactly).
//
// Complete bricks S_n: the value of the lattice function at the sample,
//   S_n(q) = Σ P_m(q) over all nodes m of the same level whose closed cube contains q,
// summed in a canonical order (m sorted by min corner z, then y, then x) so that every node
// sharing q stores the bit-identical value. Complete bricks are what the 3D-texture brick pool
// holds, so hardware trilinear filtering inside any brick is continuous across node borders.
//
// Raw node values (for `--no-bricks`): the mean of V over all cells inside the node (empty = 0).
//
// Reading: a sample (v·τ, τ) means value v = rgb/τ in a medium of density τ per voxel length; a
// path of length s voxels through it has opacity 1 − exp(−τ·s).
//
// Properties the tests rely on: a region filled with V = v gives S = v everywhere inside it
// (the weights sum to 1 at every level); the results do not depend on thread order.
#include <cstdint>

namespace vct {

constexpr int kBrickSize = 3;
constexpr int kBrickSamples = 27;  // index i + 3j + 9k

}  // namespace vct
