// Which pixel of its block a cell of the traced image traces (cone_carry.comp, which lists it for
// cone_trace.comp).
// Requires the includer's uPosition (the G-buffer's positions), uDownscale and uRotation.
//
// With uDownscale = 1 every pixel is its own cell. With B = 2 or 4, one pixel of each B×B block is
// traced; which one turns with uRotation (the pixel sample), so that accumulated samples trace
// every pixel in turn, and a block whose turn falls on sky takes the next pixel that sees a surface.

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

// The pixel cell `cell` traces and its G-buffer position (w ≤ 0: the whole block sees sky).
ivec2 tracedPixelOfCell(ivec2 cell, out vec4 position) {
    ivec2 pixel = cell;
    position = texelFetch(uPosition, pixel, 0);
    if (uDownscale > 1) {
        const ivec2 imageSize = textureSize(uPosition, 0);
        position.w = 0.0;
        for (int k = 0; k < uDownscale * uDownscale && position.w <= 0.0; ++k) {
            const ivec2 candidate = cell * uDownscale + blockPixel(k);
            if (any(greaterThanEqual(candidate, imageSize))) continue;
            pixel = candidate;
            position = texelFetch(uPosition, pixel, 0);
        }
    }
    return pixel;
}
