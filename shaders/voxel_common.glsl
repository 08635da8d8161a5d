// Voxel-space helpers shared by the voxel passes (engine/voxel/voxel_grid.hpp is the C++ twin).

uint packCell(uvec3 c) { return c.x | (c.y << 10) | (c.z << 20); }
uvec3 unpackCell(uint p) { return uvec3(p & 1023u, (p >> 10) & 1023u, (p >> 20) & 1023u); }

// Octahedral encoding of a unit vector into two 16-bit snorm values.
uint packNormal(vec3 n) {
    n /= max(abs(n.x) + abs(n.y) + abs(n.z), 1e-30);
    vec2 e = n.z >= 0.0 ? n.xy : (1.0 - abs(n.yx)) * vec2(n.x >= 0.0 ? 1.0 : -1.0, n.y >= 0.0 ? 1.0 : -1.0);
    return packSnorm2x16(e);
}
vec3 unpackNormal(uint p) {
    vec2 e = unpackSnorm2x16(p);
    vec3 n = vec3(e, 1.0 - abs(e.x) - abs(e.y));
    if (n.z < 0.0) n.xy = (1.0 - abs(n.yx)) * vec2(n.x >= 0.0 ? 1.0 : -1.0, n.y >= 0.0 ? 1.0 : -1.0);
    return normalize(n);
}
