// The voxels' light (engine/lighting/radiance_volume.hpp), shared by the radiance passes and the
// cones that read voxels directly (cone_march.glsl); included once however many includers.
#ifndef CELL_RADIANCE_GLSL
#define CELL_RADIANCE_GLSL
layout(std430, binding = SSBO_CELL_RADIANCE) buffer CellRadiance { vec4 cellRadiance[]; };  // premultiplied (L·τ, τ)
// Per cell two vec4: the share of its radiance that leaves towards each of the six axis
// directions, seen through its opacity there (radiance_normalize.comp; read by facing.glsl);
// negative on the dark side of a surface lit at an angle to the axes (darkSideSigned there).
layout(std430, binding = SSBO_CELL_EXIT_SHARES) buffer CellExitShares { vec4 cellExitShares[]; };
// Seen along an axis, a voxel's lit parts may show more than its mean radiance (a fold lit from
// above, seen from above); never more than this many times (nor less than minus as many).
const float MAX_EXIT_SHARE = 4.0;
#endif
