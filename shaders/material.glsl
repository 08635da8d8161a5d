// Material inputs set by GpuScene::draw() for every draw range, and the base-colour lookup that
// every rasterizing pass shares (G-buffer, light-view map, voxelization).
uniform sampler2D uBaseColorTexture;
uniform vec4 uBaseColor;    // linear albedo, alpha
uniform vec3 uEmissive;     // emitted radiance W/(m²·sr)
uniform float uAlphaCutoff; // < 0: opaque material
uniform int uHasTexture;

// Linear albedo and alpha at `uv`; discards texels that an alpha mask cuts away.
vec4 materialBaseColor(vec2 uv) {
    vec4 color = uBaseColor;
    if (uHasTexture != 0) color *= texture(uBaseColorTexture, uv);  // sRGB texture: already linear
    if (uAlphaCutoff >= 0.0 && color.a < uAlphaCutoff) discard;
    return color;
}

// Interpolated normal, made unit and turned to face `towards` (all surfaces are two-sided).
// A degenerate interpolated normal falls back to the triangle's geometric normal.
vec3 facingNormal(vec3 interpolated, vec3 position, vec3 towards) {
    vec3 n = interpolated;
    if (!(dot(n, n) > 1e-24)) n = cross(dFdx(position), dFdy(position));
    if (!(dot(n, n) > 0.0)) n = towards;
    n = normalize(n);
    return dot(n, towards) < 0.0 ? -n : n;
}

// Base colour with explicit texture derivatives, for passes without screen-space derivatives
// (voxelization samples at a clipped-polygon centroid). Does not discard: the caller decides.
vec4 materialBaseColorGrad(vec2 uv, vec2 dUvdx, vec2 dUvdy) {
    vec4 color = uBaseColor;
    if (uHasTexture != 0) color *= textureGrad(uBaseColorTexture, uv, dUvdx, dUvdy);
    return color;
}

bool materialCutsAway(float alpha) { return uAlphaCutoff >= 0.0 && alpha < uAlphaCutoff; }
