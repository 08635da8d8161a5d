// Brick addressing shared by the brick passes and every pass that samples bricks. Brick index =
// node index; bricks are laid out x-fastest in 3D textures ("pools") of uBrickPoolBricks.
uniform ivec3 uBrickPoolBricks;

// n / d for n ≥ 0, d > 0: a float estimate, corrected by one step. Brick lookups sit in the
// innermost loops of the cone march and the radiance filters, and x86 has no SIMD integer
// division: llvmpipe divides lane by lane, which cost those passes a tenth to a fifth of their
// time. The estimate is off by at most one, so the result is exact, whenever float(n) errs by less
// than about d: always below n = 2²⁴ (exact conversion), and for every brick index above it, since
// brickPoolLayout makes a pool's x·y plane at least the brick count to the power 2/3.
int exactQuotient(int n, int d) {
    int q = int(float(n) / float(d));
    int r = n - q * d;
    return q + (r >= d ? 1 : 0) - (r < 0 ? 1 : 0);
}

ivec3 brickOriginIn(uint brick, ivec3 bricks) {
    int b = int(brick);
    int plane = bricks.x * bricks.y;
    int z = exactQuotient(b, plane);
    int inPlane = b - z * plane;
    int y = exactQuotient(inPlane, bricks.x);
    return 3 * ivec3(inPlane - y * bricks.x, y, z);
}
ivec3 brickOrigin(uint node) { return brickOriginIn(node, uBrickPoolBricks); }

int sampleIndex(ivec3 s) { return s.x + 3 * s.y + 9 * s.z; }

// The six directions of the slab pools: index 2a for a cone travelling along +a, 2a + 1
// along −a (a = 0, 1, 2 for x, y, z).
vec3 poolDirection(int index) {
    vec3 d = vec3(0.0);
    d[index >> 1] = (index & 1) == 0 ? 1.0 : -1.0;
    return d;
}
