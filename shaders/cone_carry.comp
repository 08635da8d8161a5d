#version 450
layout(local_size_x = 8, local_size_y = 8) in;
// cone_carry (render/cone_carry.hpp; the first dispatch of the cone_trace pass in blocks): which
// cells of the traced image cone_trace.comp traces this frame.
//
// When only the camera moved since the last frame (the same geometry, lights and settings), every
// pixel that the last frame's indirect light serves (pixel_carry.glsl) takes it in
// cone_upsample.comp. A block more than half of whose pixels are served so traces no cones: its
// cell takes the carried light of its first pixel that has it (CARRIED_CELL), so that the cells
// around it that do trace still find it in their filter and upsampling windows, and its pixels
// without carried light take theirs from the cells around them, as in any frame (or trace their
// own). Every other cell that sees a surface goes on the list with the pixel of its block that it
// traces (block_pixel.glsl).
#include "traced_pixel.glsl"
#include "cone_counters.glsl"

layout(binding = TEXTURE_GBUFFER_NORMAL) uniform sampler2D uNormal;
layout(binding = TEXTURE_GBUFFER_POSITION) uniform sampler2D uPosition;
// The pixels cone_trace.comp traces, one per listed cell (packTracedPixel).
layout(std430, binding = SSBO_TRACE_CELLS) writeonly buffer TraceCells { uint traceCells[]; };
layout(rgba32f, binding = IMAGE_INDIRECT) uniform writeonly image2D uTraced;
layout(r32ui, binding = IMAGE_TRACED_PIXEL) uniform writeonly uimage2D uTracedPixel;
// For each pixel that sees a surface, in a frame that carries light: the last frame's pixel it takes
// its light from (packTracedPixel), or NO_TRACED_PIXEL; cone_upsample.comp reads it.
layout(r32ui, binding = IMAGE_CARRIED_FROM) uniform writeonly uimage2D uCarriedFrom;

uniform int uDownscale;

#include "block_pixel.glsl"
#include "pixel_carry.glsl"

// The pixel of `cell`'s block, first in the turning order, that takes the last frame's light and
// the last frame's pixel it takes it from (x < 0: none); how many of the block's pixels that see a
// surface do not take it. Records for each of them where it takes its light from.
ivec2 carriedPixelOfBlock(ivec2 cell, out ivec2 from, out int uncarried) {
    const ivec2 size = textureSize(uPosition, 0);
    ivec2 first = ivec2(-1);
    from = ivec2(-1);
    uncarried = 0;
    for (int k = 0; k < uDownscale * uDownscale; ++k) {
        const ivec2 pixel = cell * uDownscale + blockPixel(k);
        if (any(greaterThanEqual(pixel, size))) continue;
        const vec4 position = texelFetch(uPosition, pixel, 0);
        if (!(position.w > 0.0)) continue;
        const ivec2 carried = carriedPixelFor(position.xyz, normalize(texelFetch(uNormal, pixel, 0).xyz));
        imageStore(uCarriedFrom, pixel, uvec4(carried.x < 0 ? NO_TRACED_PIXEL : packTracedPixel(carried)));
        if (carried.x < 0) {
            ++uncarried;
        } else if (first.x < 0) {
            first = pixel;
            from = carried;
        }
    }
    return first;
}

void main() {
    const ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(cell, imageSize(uTraced)))) return;
    vec4 position;
    const ivec2 pixel = tracedPixelOfCell(cell, position);
    if (position.w > 0.0 && uCarry != 0) {
        ivec2 from;
        int uncarried;
        const ivec2 carriedPixel = carriedPixelOfBlock(cell, from, uncarried);
        if (carriedPixel.x >= 0 && 2 * uncarried < uDownscale * uDownscale) {
            imageStore(uTraced, cell, texelFetch(uCarriedIrradiance, from, 0));
            imageStore(uTracedPixel, cell, uvec4(packTracedPixel(carriedPixel) | CARRIED_CELL));
            return;
        }
    }
    if (!(position.w > 0.0)) {  // sky: no GI work
        imageStore(uTraced, cell, vec4(0.0, 0.0, 0.0, 1.0));
        if (uDownscale > 1)
            imageStore(uTracedPixel, cell, uvec4(NO_TRACED_PIXEL));
        else
            count64(CONE_COUNTER_SKY_PIXELS, 1u);  // in blocks cone_upsample.comp counts the sky's pixels
        return;
    }
    if (uDownscale > 1) imageStore(uTracedPixel, cell, uvec4(packTracedPixel(pixel)));
    traceCells[atomicAdd(coneCounters[CONE_COUNTER_TRACE_CELLS], 1u)] = packTracedPixel(pixel);
}
