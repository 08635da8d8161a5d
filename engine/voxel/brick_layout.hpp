#pragma once
// What a brick sample means (DESIGN 5.4). Two kinds of bricks share one lattice: the albedo
// bricks, filtered linearly (below, to "Reading"), which the voxel views show; and the slab bricks
// of opacity and radiance that cones read (last section, "Slabs"). The GPU passes (bricks.cpp,
// bricks_mip.cpp, radiance_filter.cpp) and the CPU references in tests/reference/ implement
// exactly these definitions.
//
// Cells and values. The finest voxels ("cells") are unit cubes [c, c+1)³ of voxel space. An
// occupied cell has albedo ρ (mean of its fragments) and opacity α = min(1, A) where A is the
// surface area inside it in voxel-face units (a plane straight through a cell has A = 1), and
// opacity along each axis α_a = min(1, A_a), A_a the area projected along a, except that along a
// triangle's projection axis a cell the triangle crosses in depth with others of its pixel column
// counts the column's whole coverage (voxelize.frag: a ray along the column meets the triangle in
// one of them; its area split among them would let light through). The albedo bricks
// filter optical depth τ = −ln(1 − min(α, 0.999)) (per voxel length) weighted: V(c) = (ρ·τ, τ).
// Empty cells have V = 0.
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
//
// Slabs. What a cone needs of a region is how much it blocks and how much light it sends along
// the cone, and both depend on the direction: a one-voxel wall must stay opaque along its normal
// at every level, a node a quarter covered by a pillar must pass three quarters of a cone's light,
// and the dark side of a lit wall must look dark. Averaging α or τ over a node's volume gets the
// first or the second wrong (the mean of exp(−τ) is not exp(−mean τ)); and a value without
// direction cannot tell the sides of a wall apart. So each sample q of spacing h holds, for each of
// the six axis directions ±a, its slab: the box that starts at q and reaches h along ±a, with
// the cross-section of q's lattice cell (h × h around q). What a cone standing at q travelling
// along ±a crosses first.
//   Opacity: the effective density τ±a = −ln T / h, T the transmittance along ±a through the slab
//     averaged over its cross-section. Leaves (h = 1): the slab holds halves of the 4 cells ahead
//     of q, T = mean of (1 − α_a). Above: the slab is two child slabs long (at 2Q and 2Q ± 1
//     along a, transmittances multiply), and across, the child slabs around 2Q are averaged with
//     the ¼ ½ ¼ tent per axis (each child's cross-section overlaps the parent's by that much).
//   Radiance: what reaches the slab's front face, averaged over its cross-section, S±a. Leaves:
//     the mean over the 4 cells ahead of α_a · L · f, L the cell's radiance and f the share of it
//     that leaves against ±a (its lit-side normal N: shaders/facing.glsl). Above: front to back
//     along the slab, S = S_front + T_front · S_back per child column, tent-averaged across.
//     Stored premultiplied as L·τ±a with L = S / (1 − T), the radiance of a uniform medium of the
//     slab's opacity that sends S (so that trilinear interpolation between samples stays
//     consistent with the interpolated density).
// Light seen from the dark side of a wall is then what lies on that side, at every level.
//
// Reading: a cone at p reads, for each direction, the samples one spacing ahead of p along it
// (so no sample behind p, whose slab could hold what lies behind the cone, is interpolated; the
// point ahead may lie in a node that holds geometry where p's own node is empty), and
// combines the six with the weights of its spread of directions (shaders/cone_trace.comp).
#include <cstdint>

namespace vct {

constexpr int kBrickSize = 3;
constexpr int kBrickSamples = 27;  // index i + 3j + 9k

}  // namespace vct
