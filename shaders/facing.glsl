// Which share of a leaf voxel's outgoing light travels back along a cone going along
// `coneDirection`. A lit surface sends its reflected light to the side the light came from: a
// cone must not gather the floor it starts from, or a surface lit from the other side of a wall.
// A voxel cannot say which of its parts faces which way, so this uses the mean lit-side normal
// N of the voxel's photons, already shortened by the reflected share of its radiance
// (radiance_normalize.comp), and the emitted share e of its radiance:
//   * the voxel's radiance L counts the reflected light of both sides over one side's area, so
//     the side N points to shows L·(1 + |N| + e)/2 and the other side L·(1 − |N| + e)/2: their
//     difference is the directional part |N|, and emission (which leaves both ways) adds to both;
//     one lit side gives 1 and 0, a wall lit equally from both sides ½ each, pure emission 1 each;
//   * between the sides the share changes over a few degrees either side of edge-on (all of the
//     front share from 4° in front of the surface on, none from 4° behind it on).
// `direction` is a direction sample (N·τ, τ).
float facingShare(vec4 direction, float emittedShare, vec3 coneDirection) {
    vec3 n = direction.a > 1e-6 ? direction.rgb / direction.a : vec3(0.0);
    float directional = min(length(n), 1.0);
    float back = clamp(0.5 * (1.0 - directional + emittedShare), 0.0, 1.0);
    if (directional <= 0.0) return back;
    float front = clamp(0.5 * (1.0 + directional + emittedShare), 0.0, 1.0);
    return back + (front - back) * clamp(0.5 + 8.0 * dot(n / directional, -coneDirection), 0.0, 1.0);
}
