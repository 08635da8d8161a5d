// The radiance pool of the six directions (lighting/radiance_volume.hpp): one brick per node and
// direction, each direction's bricks laid out as uDirectionalBricks and the six stacked along z in
// the order +x −x +y −y +z −z. Requires bricks_common.glsl.
uniform ivec3 uDirectionalBricks;

// Where the bricks of direction `direction` (0..5) start, in texels.
ivec3 directionOffset(int direction) { return ivec3(0, 0, 3 * direction * uDirectionalBricks.z); }

// The first texel of node `node`'s brick for direction `direction`.
ivec3 directionalBrickOrigin(uint node, int direction) {
    return brickOriginIn(node, uDirectionalBricks) + directionOffset(direction);
}
