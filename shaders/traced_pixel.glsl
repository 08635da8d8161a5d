// Which pixel a cell of the traced image took its cones from: at half resolution cone_trace.comp
// traces one pixel of each 2×2 block and records it (x | y << 16) for the passes that use the
// cell's irradiance (cone_upsample.comp, indirect_filter.comp).

// A block that sees only sky traced no pixel.
const uint NO_TRACED_PIXEL = 0xffffffffu;

uint packTracedPixel(ivec2 pixel) { return uint(pixel.x) | (uint(pixel.y) << 16); }
ivec2 unpackTracedPixel(uint code) { return ivec2(code & 0xffffu, code >> 16); }
