#version 450
layout(local_size_x = 8, local_size_y = 8, local_size_z = CONE_LANES) in;
// cone_trace (DESIGN §4 pass 12, §5.5): diffuse cones over the hemisphere around the normal march
// through the radiance bricks (cone_march.glsl) and add up to the indirect irradiance E.
// Output: E (rgb) and ambient visibility (a: 1 = nothing in the way).
//
// With uDownscale = 1 every pixel is traced, straight into the indirect image. With B = 2 or 4, one
// pixel of each B×B block is traced into an image 1/B the size per side, with the pixel it traced
// (or NO_TRACED_PIXEL when the whole block is sky); cone_upsample.comp then gives every pixel its
// irradiance from the traced pixels that share its surface. Which pixel of a block is traced turns
// with uRotation (the pixel sample), so that accumulated samples trace every pixel in turn.
// The work group's z holds the lanes that share each pixel's cones (cone_lanes.glsl).
#include "cone_march.glsl"
#include "cone_trace_common.glsl"

layout(binding = TEXTURE_GBUFFER_NORMAL) uniform sampler2D uNormal;
layout(binding = TEXTURE_GBUFFER_POSITION) uniform sampler2D uPosition;
layout(r32ui, binding = IMAGE_TRACED_PIXEL) uniform writeonly uimage2D uTracedPixel;

uniform int uRotation;

const ivec2 kBlockOrder[4] = ivec2[](ivec2(0, 0), ivec2(1, 1), ivec2(1, 0), ivec2(0, 1));
// For 4×4 blocks: the 4×4 ordered-dither sequence, each step as far from the ones before as it
// can be (so that a few accumulated samples already spread over the block), shifted to start
// next to the block's centre, where the upsampling's bilinear weights place the traced point.
const ivec2 kBlockOrder4[16] = ivec2[](ivec2(1, 1), ivec2(3, 3), ivec2(3, 1), ivec2(1, 3), ivec2(2, 2), ivec2(0, 0),
                                       ivec2(0, 2), ivec2(2, 0), ivec2(2, 1), ivec2(0, 3), ivec2(0, 1), ivec2(2, 3),
                                       ivec2(1, 2), ivec2(3, 0), ivec2(3, 2), ivec2(1, 0));

ivec2 blockPixel(int k) {
    return uDownscale == 2 ? kBlockOrder[(k + uRotation) & 3] : kBlockOrder4[(k + uRotation) & 15];
}

void main() {
    const ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
    const bool inImage = all(lessThan(cell, imageSize(uIndirect)));
    const ivec2 imageSize = textureSize(uPosition, 0);
    // The pixel this invocation traces: itself, or the first pixel of its block, in the turning
    // order, that sees a surface.
    ivec2 pixel = cell;
    vec4 position = inImage ? texelFetch(uPosition, pixel, 0) : vec4(0.0);
    if (inImage && uDownscale > 1) {
        position.w = 0.0;
        for (int k = 0; k < uDownscale * uDownscale && position.w <= 0.0; ++k) {
            const ivec2 candidate = cell * uDownscale + blockPixel(k);
            if (any(greaterThanEqual(candidate, imageSize))) continue;
            pixel = candidate;
            position = texelFetch(uPosition, pixel, 0);
        }
    }
    const bool traces = position.w > 0.0;  // else sky (or outside the image): no GI work
#ifdef STORE_CONE_SAMPLES
    if (inImage) coneSampleCell = cell;
#endif
    const vec4 part = traces ? gatherPixel(pixel, position.xyz, normalize(texelFetch(uNormal, pixel, 0).xyz)) : vec4(0.0);
    const vec4 gathered = sumConeLanes(part);
    if (!inImage || !storesConeLanes()) return;
    if (!traces) {
        imageStore(uIndirect, cell, vec4(0.0, 0.0, 0.0, 1.0));
        if (uDownscale > 1)
            imageStore(uTracedPixel, cell, uvec4(NO_TRACED_PIXEL));
        else if (!continuesTrace())
            count64(CONE_COUNTER_SKY_PIXELS, 1u);
        return;
    }
    storeTraced(cell, finishTrace(gathered));
    if (uDownscale > 1) imageStore(uTracedPixel, cell, uvec4(packTracedPixel(pixel)));
}
