// Which share of a leaf sample's reflected light travels back along a cone going along
// `coneDirection`. A lit surface sends its reflected light to the side the light came from: a
// cone must not gather the floor it starts from, or a surface lit from the other side of a wall.
// A voxel cannot say which of its parts faces which way, so this uses the mean lit-side normal
// N of the voxels' photons (|N| = 1 for one lit side): all of it in front of the surface from 4°
// above on, none behind it from 4° below on, half edge-on; where N is short (lit from several
// sides, or emission, which leaves both ways) more of it, all at N = 0.
// `direction` is a direction sample (N·τ, τ).
float facingShare(vec4 direction, vec3 coneDirection) {
    vec3 n = direction.a > 1e-6 ? direction.rgb / direction.a : vec3(0.0);
    return clamp(1.0 - 0.5 * length(n) + 8.0 * dot(n, -coneDirection), 0.0, 1.0);
}
