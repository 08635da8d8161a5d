// Which share of a leaf voxel's outgoing radiance L travels back along a cone going along the
// pool direction i (+x −x +y −y +z −z for i = 0..5), as a factor on L seen through the voxel's
// opacity along that axis (radiance_normalize.comp computes the six from the voxel's photons;
// negative on the dark side of a surface lit at an angle to the axes, for the cones' sum).
// A lit surface sends its reflected light to the side the light came from: a cone must not
// gather the floor it starts from, or a surface lit from the other side of a wall; and a folded or
// curved surface sends more of it towards the side its lit parts face. Emission leaves both ways.
// Requires cell_radiance.glsl; `cell` indexes the cell level.
float exitShare(uint cell, int i) { return cellExitShares[2u * cell + uint(i >> 2)][i & 3]; }

// All six shares of `cell` in pool-direction order, from two reads of the buffer instead of six.
void exitShares(uint cell, out float shares[6]) {
    const vec4 xy = cellExitShares[2u * cell], z = cellExitShares[2u * cell + 1u];
    shares = float[6](xy.x, xy.y, xy.z, xy.w, z.x, z.y);
}

// What a ray travelling along pool direction i meets of voxel `cell`, whose opacity along that
// axis is `alpha`: (L·f·τ, τ), its radiance L times its exit share f that way, τ = −ln(1 − α)
// the optical depth of the voxel's window along the axis.
vec4 voxelSeenAlong(uint cell, int i, float alpha) {
    alpha = min(alpha, MAX_OPACITY);
    if (alpha <= 0.0) return vec4(0.0);
    float tau = -log(1.0 - alpha);
    vec4 stored = cellRadiance[cell];
    vec3 radiance = stored.a > 0.0 ? stored.rgb / stored.a : vec3(0.0);
    return vec4(radiance * exitShare(cell, i) * tau, tau);
}

// Stores the six shares of `cell`: towards +x −x +y −y (`xy`), +z −z (`z`), as exitShare reads them.
// Keeps the lit place beside them.
void storeExitShares(uint cell, vec4 xy, vec2 z) {
    cellExitShares[2u * cell] = xy;
    cellExitShares[2u * cell + 1u].xy = z;
}

// Where in `cell` its reflected light comes from: the flux-weighted mean place of its photons
// across the cell (0..1 per axis), kept beside its exit shares in 6 bits per axis (a float holding
// an integer, exact on every GPU; 0: not known). A cell holds its surface without where it lies
// in it; a narrow cone inside the cell uses the place to tell whether the lit surface lies ahead
// of it or behind it (cone_march.glsl, sampleVoxels). 48 steps, so that the places of evenly lit
// halves, quarters, thirds and eighths of a cell are steps themselves, not ties between two that
// the rounding of the photons' positions (which the scene's scale changes) would break: with 63,
// a cell lit evenly across an axis, mean place ½, rounded to 31 or 32 at random, and a cone
// between the two saw its own voxel's light or not.
const float LIT_PLACE_STEPS = 48.0;
void storeLitPlace(uint cell, bool known, vec3 place) {
    uvec3 q = uvec3(round(clamp(place, 0.0, 1.0) * LIT_PLACE_STEPS));
    cellExitShares[2u * cell + 1u].z = known ? float(1u + q.x + 64u * q.y + 4096u * q.z) : 0.0;
}
bool litPlace(uint cell, out vec3 place) {
    uint code = uint(cellExitShares[2u * cell + 1u].z);
    place = vec3(uvec3(code - 1u, (code - 1u) >> 6, (code - 1u) >> 12) & 63u) / LIT_PLACE_STEPS;
    return code != 0u;
}
