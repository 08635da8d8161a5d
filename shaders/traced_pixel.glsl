// Which pixel a cell of the traced image took its cones from: in blocks cone_trace.comp traces one
// pixel of each 2×2 or 4×4 block and records it (x | y << 16) for the passes that use the
// cell's irradiance (cone_upsample.comp, indirect_filter.comp), and how much a traced point
// counts for another pixel's surface in those passes.

// A block that sees only sky traced no pixel.
const uint NO_TRACED_PIXEL = 0xffffffffu;
// A block whose pixels all took the last frame's light (cone_carry.comp) traced no cones either:
// its cell holds that light at the pixel named, which the passes after it read as any traced
// cell's, except the shared cones (it has none).
const uint CARRIED_CELL = 0x80000000u;

uint packTracedPixel(ivec2 pixel) { return uint(pixel.x) | (uint(pixel.y) << 16); }
ivec2 unpackTracedPixel(uint code) { return ivec2(code & 0xffffu, (code >> 16) & 0x7fffu); }

// Irradiance varies slowly along a surface but jumps across edges, so a traced point counts for a
// surface point in so far as it lies on the same surface: normals within ~25° keep most of the
// weight (cos⁸), and a point `planeVoxels` off the tangent plane keeps e⁻¹ (a parallel surface a
// step away, a floor under a table seen beside it, is another surface however close its points
// lie). `offset`: from the surface point to the traced one, in voxels.
float sameSurfaceWeight(vec3 normal, vec3 tracedNormal, vec3 offset, float planeVoxels) {
    float alike = max(dot(normal, tracedNormal), 0.0);
    float alike2 = alike * alike, alike4 = alike2 * alike2;
    float offPlane = dot(normal, offset) / planeVoxels;
    return alike4 * alike4 * exp(-offPlane * offPlane);
}
