// The voxels' light (engine/lighting/radiance_volume.hpp), shared by the radiance passes and the
// cones that read voxels directly (cone_march.glsl); included once however many includers.
#ifndef CELL_RADIANCE_GLSL
#define CELL_RADIANCE_GLSL
layout(std430, binding = SSBO_CELL_RADIANCE) buffer CellRadiance { vec4 cellRadiance[]; };  // premultiplied (L·τ, τ)
// The mean lit-side normal of the voxel's reflected light (radiance_normalize), premultiplied
// (N·τ, τ); bound at SSBO_CELL_RADIANCE in place of CellRadiance when the brick passes filter it.
layout(std430, binding = SSBO_CELL_DIRECTION) buffer CellDirection { vec4 cellDirection[]; };
#endif
