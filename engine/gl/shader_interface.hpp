#pragma once
// The contract between the C++ passes and their GLSL: binding points and shared constants,
// written once here. The shader loader (gl/shader.cpp) hands every entry to every shader as a
// `#define NAME value`, so a shader writes `layout(std430, binding = SSBO_NODE_CHILD)` where the
// C++ side binds `gl::SSBO_NODE_CHILD`: the two cannot disagree, and a misspelt name fails to
// compile on either side.
//
// A binding point is only meaningful within one program, so different names may share a number
// (image unit 0 is the fragment list in voxelization and the partial bricks in the brick passes);
// the names say what each program finds there.

// clang-format off
#define VCT_SHADER_INTERFACE(X)                                                                   \
    /* Storage buffers (GL_SHADER_STORAGE_BUFFER). */                                             \
    X(SSBO_FRAGMENT_COUNTER, 0)      /* voxelize: fragments appended */                          \
    X(SSBO_PREFIX_VALUES, 0)         /* prefix_sum: values scanned in place */                    \
    X(SSBO_CALIBRATION_DATA, 0)      /* perf_calibration: scattered reads and atomics */          \
    X(SSBO_PREFIX_BLOCK_SUMS, 1)     /* prefix_sum: per-block totals */                           \
    X(SSBO_NODE_CHILD, 1)            /* octree.glsl: first child of each node */                  \
    X(SSBO_NODE_MASK, 2)             /* octree.glsl: existing child slots */                      \
    X(SSBO_NODE_COORD, 3)            /* octree.glsl: packed coordinate at the node's level */     \
    X(SSBO_NODE_PARENT, 4)           /* octree.glsl */                                            \
    X(SSBO_NODE_NEIGHBOUR, 5)        /* octree.glsl: six per node */                              \
    X(SSBO_CHILD_COUNTS, 6)          /* svo_alloc: children per node, then their prefix sum */    \
    X(SSBO_LEAF_STATUS, 6)           /* svo_leaves_normalize: overflow count, largest count */    \
    X(SSBO_LIST_COUNTS, 6)           /* radiance_common.glsl: touched and border list lengths */  \
    X(SSBO_CELL_VALUES, 7)           /* per voxel: RGBA8 albedo+opacity (or opacity by axis) */   \
    X(SSBO_CELL_NORMAL, 8)                                                                        \
    X(SSBO_CELL_AREA, 9)                                                                          \
    X(SSBO_CELL_FRAGMENTS, 10)                                                                    \
    X(SSBO_CELL_EMISSIVE, 11)                                                                     \
    X(SSBO_RAW_VALUE, 12)            /* per node: mean of its cells (`--no-bricks`) */            \
    X(SSBO_RADIANCE_ACCUMULATORS, 13)                                                             \
    X(SSBO_TOUCHED_FLAG, 14)                                                                      \
    X(SSBO_TOUCHED_LIST, 15)                                                                      \
    X(SSBO_BORDER_FLAG, 16)                                                                       \
    X(SSBO_BORDER_LIST, 17)                                                                       \
    X(SSBO_CELL_RADIANCE, 18)        /* per voxel: (L·τ, τ), or the channel being filtered */     \
    X(SSBO_INDIRECT_ARGS, 19)                                                                     \
    X(SSBO_CELL_COLUMNS, 20)         /* per voxel: its triangles' column partners (svo_leaves) */  \
    X(SSBO_MATERIALS, 21)            /* {baseColor, emissive} per material */                     \
    X(SSBO_CONE_COUNTERS, 22)                                                                     \
    X(SSBO_CELL_EXIT_SHARES, 23)                                                                  \
    X(SSBO_BOUNCE_BASE, 24)          /* bounce_gather: every cell's first-bounce radiance */      \
    X(SSBO_CELL_OPACITY, 25)                                                                      \
    X(SSBO_BOUNCE_LIST, 26)          /* bounce_gather: cells that gather their own bounce */      \
    X(SSBO_OWN_TRACE_PIXELS, 27)     /* cone_upsample: pixels that trace their own cones */        \
    X(SSBO_CONE_SAMPLES, 28)         /* cone_trace → cone_reuse: each narrow cone's own result */  \
    X(SSBO_TRACE_CELLS, 29)          /* cone_carry → cone_trace: the cells to trace */             \
    X(SSBO_CONE_LANE_PARTS, 30)      /* cone_trace with lanes: each lane's part, added after */    \
    X(SSBO_OWN_TRACE_SMOOTHED, 31)   /* cone_upsample: the own-traced pixels' averaged light */   \
    /* Image units (glBindImageTexture). */                                                       \
    X(IMAGE_FRAGMENTS, 0)            /* voxel-fragment list, RGBA32UI */                          \
    X(IMAGE_FRAGMENT_NODE, 1)        /* the node of each fragment, R32UI */                       \
    X(IMAGE_CELL_ACCUMULATORS, 3)                                                                 \
    X(IMAGE_PROJECTED_AREA, 4)                                                                    \
    X(IMAGE_PARTIAL_BRICKS, 0)                                                                    \
    X(IMAGE_CHILD_PARTIAL_BRICKS, 1)                                                              \
    X(IMAGE_BRICK_POOL, 1)                                                                        \
    X(IMAGE_OPACITY_PLUS, 1)         /* bricks_opacity: the pool of slabs along +x +y +z */       \
    X(IMAGE_OPACITY_MINUS, 2)        /* and along −x −y −z */                                     \
    X(IMAGE_DIRECTIONAL_RADIANCE, 2) /* the radiance pool of the six directions */                \
    X(IMAGE_DIRECT, 0)                                                                            \
    X(IMAGE_INDIRECT, 0)                                                                          \
    X(IMAGE_TRACED_PIXEL, 1)         /* cone_carry in blocks: the pixel each block traced */ \
    X(IMAGE_PIXEL_AT, 3)             /* cone_upsample: the point each pixel's light belongs to */ \
    X(IMAGE_PIXEL_NORMAL, 4)         /* and its normal */                                         \
    X(IMAGE_CARRIED_FROM, 5)         /* cone_carry: the last frame's pixel each pixel takes light from */ \
    X(IMAGE_NEAR_VISIBILITY, 1)      /* near_detail: each pixel's visibility within the cones' start */ \
    X(IMAGE_VOXEL_VIEW, 0)                                                                        \
    X(IMAGE_HDR, 0)                                                                               \
    X(IMAGE_LDR, 1)                                                                               \
    X(IMAGE_HDR_SUM, 2)              /* composite: the sum of the samples averaged so far */      \
    X(IMAGE_INDIRECT_SUM, 3)         /* composite: the weighted sum of their indirect light */    \
    /* Texture units (samplers). */                                                               \
    X(TEXTURE_BASE_COLOR, 0)         /* material.glsl, in every pass that rasterizes the scene */ \
    X(TEXTURE_GBUFFER_ALBEDO, 0)                                                                  \
    X(TEXTURE_GBUFFER_NORMAL, 1)                                                                  \
    X(TEXTURE_GBUFFER_POSITION, 2)                                                                \
    X(TEXTURE_GBUFFER_EMISSIVE, 3)                                                                \
    X(TEXTURE_GBUFFER_GEOMETRIC_NORMAL, 7) /* cone_trace, cone_upsample: the triangle's own side */ \
    X(TEXTURE_SHADOW_MAP, 3)         /* direct_lighting: the light-view depth */                  \
    X(TEXTURE_DIRECT, 4)                                                                          \
    X(TEXTURE_DEBUG_IMAGE, 5)                                                                     \
    X(TEXTURE_INDIRECT, 6)                                                                        \
    X(TEXTURE_OPACITY_PLUS, 3)       /* opacity of the slabs along +x +y +z (brick_layout.hpp) */ \
    X(TEXTURE_OPACITY_MINUS, 4)      /* along −x −y −z */                                         \
    X(TEXTURE_DIRECTIONAL_RADIANCE, 6) /* the radiance pool of the six directions */              \
    X(TEXTURE_CARRIED_AT, 8)         /* pixel_carry.glsl: the last frame's IMAGE_PIXEL_AT */      \
    X(TEXTURE_CARRIED_NORMAL, 9)     /* and IMAGE_PIXEL_NORMAL */                                 \
    X(TEXTURE_CARRIED_IRRADIANCE, 10) /* and its indirect irradiance */                           \
    X(TEXTURE_CARRIED_FROM, 11)      /* cone_upsample: IMAGE_CARRIED_FROM */                        \
    X(TEXTURE_TRACED_IRRADIANCE, 12) /* cone_upsample, indirect_filter: what the cones gathered */ \
    X(TEXTURE_TRACED_PIXEL, 13)      /* cone_upsample, indirect_filter: the pixel each block traced */ \
    X(TEXTURE_NEAR_FIELD_DIRECT, 14) /* cone_trace, cone_upsample: near_field.glsl's direct light */ \
    X(TEXTURE_NEAR_FIELD_EMISSIVE, 15) /* and emission */                                         \
    X(TEXTURE_NEAR_VISIBILITY, 8)    /* near_detail: IMAGE_NEAR_VISIBILITY */                     \
    X(TEXTURE_VIEW_ALBEDO_BRICKS, 1) /* voxel_view: the albedo pool */                     \
    X(TEXTURE_LIGHT_POSITION, 0)     /* inject: the light-view map's photons */                   \
    X(TEXTURE_LIGHT_FLUX, 1)                                                                      \
    X(TEXTURE_LIGHT_NORMAL, 2)                                                                    \
    /* Sizes shared by both sides. */                                                             \
    X(MAX_OCTREE_LEVELS, 11)         /* node levels 0..L−1 plus the cell level L, L ≤ 10 */       \
    X(MAX_CONES, 16)                 /* the largest cone set */                                   \
    X(CELL_ACCUMULATOR_FIELDS, 16)   /* svo_leaves: 32-bit sums per voxel */                      \
    X(PROJECTED_AREA_FIELDS, 12)     /* svo_leaves: area facing +x −x +y −y +z −z, 64 bits each */  \
    X(RADIANCE_ACCUMULATOR_WORDS, 24) /* inject: flux, lit sides, lit place (12 × 64 bits) */   \
    X(BORDER_COUNT_SLOT, 12)         /* list counts: touched [0, 12), border [12, 24) */          \
    X(MISSED_COUNT_SLOT, 24)         /* list counts: photons that found no voxel */               \
    X(BOUNCE_LIST_COUNT_SLOT, 25)    /* list counts: cells that gather their own bounce */        \
    X(SECOND_SHARE_COUNT_SLOT, 26)   /* list counts: cells that share a leaf's second gather */    \
    X(LIST_COUNT_SLOTS, 27)                                                                       \
    X(CONE_COUNTER_WORDS, 12)        /* cone counters: five 64-bit counts, two list lengths */    \
    X(OWN_TRACE_COUNT_SLOT, 10)      /* cone counters: cone_upsample's pixels tracing their own */ \
    X(TRACE_CELL_COUNT_SLOT, 11)     /* cone counters: cone_carry's cells for cone_trace */
// clang-format on

#include "gl/gl.hpp"

namespace vct::gl {

#define VCT_SHADER_INTERFACE_ENUM(name, value) name = value,
enum ShaderInterface : GLuint { VCT_SHADER_INTERFACE(VCT_SHADER_INTERFACE_ENUM) };
#undef VCT_SHADER_INTERFACE_ENUM

}  // namespace vct::gl
