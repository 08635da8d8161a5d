// The surface point a cell of the traced image stands for, for the passes after cone_trace.comp
// that work on that image (indirect_filter.comp, cone_reuse.comp). Requires traced_pixel.glsl and
// the includer's uDownscale, uTracedPixel (usampler2D), uPosition and uNormal.

// The G-buffer pixel whose point cell `cell` stands for (the cell itself at full resolution, else
// the pixel its block traced), its scene-local position and unit normal; false where it saw only sky.
bool pointOf(ivec2 cell, out ivec2 pixel, out vec3 position, out vec3 normal) {
    pixel = cell;
    if (uDownscale > 1) {
        const uint traced = texelFetch(uTracedPixel, cell, 0).r;
        if (traced == NO_TRACED_PIXEL) return false;
        pixel = unpackTracedPixel(traced);
    }
    const vec4 p = texelFetch(uPosition, pixel, 0);
    position = p.xyz;
    normal = normalize(texelFetch(uNormal, pixel, 0).xyz);
    return p.w > 0.0;
}

// Whether cell `cell` holds light carried from the last frame rather than its own cones
// (cone_carry.comp).
bool carriedCell(ivec2 cell) {
    if (uDownscale == 1) return false;
    const uint traced = texelFetch(uTracedPixel, cell, 0).r;
    return traced != NO_TRACED_PIXEL && (traced & CARRIED_CELL) != 0u;
}
