// Brick addressing shared by the brick passes and every pass that samples bricks. Brick index =
// node index; bricks are laid out x-fastest in 3D textures ("pools") of uBrickPoolBricks.
uniform ivec3 uBrickPoolBricks;

ivec3 brickOriginIn(uint brick, ivec3 bricks) {
    int b = int(brick);
    return 3 * ivec3(b % bricks.x, (b / bricks.x) % bricks.y, b / (bricks.x * bricks.y));
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
