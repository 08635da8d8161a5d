// Brick addressing shared by the brick passes and every pass that samples bricks.
// Brick index = node index; bricks are laid out x-fastest in a 3D texture of uBrickPoolBricks.
uniform ivec3 uBrickPoolBricks;

ivec3 brickOrigin(uint node) {
    int b = int(node);
    return 3 * ivec3(b % uBrickPoolBricks.x, (b / uBrickPoolBricks.x) % uBrickPoolBricks.y,
                     b / (uBrickPoolBricks.x * uBrickPoolBricks.y));
}

int sampleIndex(ivec3 s) { return s.x + 3 * s.y + 9 * s.z; }
