// Material inputs set by GpuScene::draw() for every draw range, and the base-colour lookup that
// every rasterizing pass shares (G-buffer, light-view map, voxelization).
layout(binding = TEXTURE_BASE_COLOR) uniform sampler2D uBaseColorTexture;
uniform vec4 uBaseColor;    // linear albedo, alpha
uniform vec3 uEmissive;     // emitted radiance W/(m²·sr)
uniform float uAlphaCutoff; // < 0: opaque material
uniform int uHasTexture;
uniform int uMaterialIndex; // into the materials buffer (GpuScene)
uniform int uVertexColors;  // 0: every vertex of the draw is white; the interpolated colour is
                            // then not used (interpolating 1 is not always exactly 1)
uniform float uSampleFootprint;  // G-buffer: the share of the pixel its lookups filter over (render/pixel_samples.hpp)

vec3 materialVertexColor(vec3 interpolated) { return uVertexColors != 0 ? interpolated : vec3(1.0); }

// The base-colour texture averaged over the pixel's footprint in it, an ellipse whose axes the
// screen derivatives of `uv` give, shrunk by `share` (a later pixel sample's, keeping its shape):
// up to FOOTPRINT_PROBES mipmapped lookups spread along its longer axis, each filtering a stretch
// as long as the shorter axis is wide (a floor seen at a grazing angle covers a long thin strip of
// its texture per pixel; one lookup would blur it to the strip's length across as well). The
// texture's sampler must filter isotropically. This is the anisotropic filter of a GPU made
// explicit: against the path tracer, which averages each pixel's area, it came closer than
// llvmpipe's own anisotropic filtering on every Sponza preset, in less time, and it gives the same
// image on every driver (whose anisotropic filters spread their probes over the whole footprint
// whatever the mip-level bias, so that jittered samples could not shrink them).
const int FOOTPRINT_PROBES = 8;
vec4 footprintTexel(vec2 uv, float share) {
    vec2 size = vec2(textureSize(uBaseColorTexture, 0));
    vec2 alongX = dFdx(uv) * share, alongY = dFdy(uv) * share;
    float lengthX = length(alongX * size), lengthY = length(alongY * size);
    vec2 major = lengthX >= lengthY ? alongX : alongY;
    float majorLength = max(lengthX, lengthY), minorLength = min(lengthX, lengthY);
    // Written so that a non-finite ratio (UVs so large that their derivatives overflow) takes the
    // most lookups instead of an undefined count.
    float ratio = majorLength / max(minorLength, 1e-6);
    int probes = ratio < float(FOOTPRINT_PROBES) ? int(max(ceil(ratio), 1.0)) : FOOTPRINT_PROBES;
    float lod = log2(max(majorLength / float(probes), 1e-6));
    vec4 sum = vec4(0.0);
    for (int k = 0; k < probes; ++k)
        sum += textureLod(uBaseColorTexture, uv + major * ((float(k) + 0.5) / float(probes) - 0.5), lod);
    return sum / float(probes);
}

// The material's colour and alpha for a texel (linear: sRGB textures are decoded by the sampler)
// on a surface of vertex colour `vertexColor` (glTF: it multiplies the base colour); discards
// what an alpha mask cuts away.
vec4 materialColorWith(vec4 texel, vec3 vertexColor) {
    vec4 color = uBaseColor * vec4(materialVertexColor(vertexColor), 1.0) * texel;
    if (uAlphaCutoff >= 0.0 && color.a < uAlphaCutoff) discard;
    return color;
}

// Linear albedo and alpha at `uv` (the texture's coordinates, material_vertex.glsl), the texture
// filtered by its sampler (light-view maps: anisotropic).
vec4 materialBaseColor(vec2 uv, vec3 vertexColor) {
    return materialColorWith(uHasTexture != 0 ? texture(uBaseColorTexture, uv) : vec4(1.0), vertexColor);
}

// The same over the G-buffer sample's share of the pixel's footprint (footprintTexel): the whole
// pixel for a plain frame; later pixel samples filter less and leave the rest to the jitter.
vec4 materialBaseColorOverPixel(vec2 uv, vec3 vertexColor) {
    if (uHasTexture == 0) return materialBaseColor(uv, vertexColor);
    return materialColorWith(footprintTexel(uv, uSampleFootprint), vertexColor);
}

// The triangle's unit geometric normal turned to face `towards` (all surfaces are two-sided):
// exact from the position's derivatives, which the whole pixel quad takes on one triangle's plane.
vec3 facingGeometricNormal(vec3 position, vec3 towards) {
    vec3 dx = dFdx(position), dy = dFdy(position);
    vec3 geometric = cross(dx, dy);
    // The squared length of that cross product goes with the fourth power of the scene's scale and
    // leaves float's range beyond about 1e9 scene units per pixel (and below about 1e-9): then the
    // derivatives are first brought to unit size.
    float length2 = dot(geometric, geometric);
    if (!(length2 > 1e-30 && length2 < 1e30)) {
        dx /= max(max(abs(dx.x), abs(dx.y)), max(abs(dx.z), 1e-37));
        dy /= max(max(abs(dy.x), abs(dy.y)), max(abs(dy.z), 1e-37));
        geometric = cross(dx, dy);
    }
    if (!(dot(geometric, geometric) > 0.0)) geometric = towards;
    geometric = normalize(geometric);
    return dot(geometric, towards) < 0.0 ? -geometric : geometric;
}

// Interpolated normal, made unit and turned to the side of the triangle its facing geometric
// normal (facingGeometricNormal) shows. Turning the interpolated normal itself to face the viewer
// would flip it wherever smooth shading tilts it past edge-on (a curtain's folds seen at a grazing
// angle) and point it into the surface: cones would then start behind it. A degenerate
// interpolated normal falls back to the geometric one.
vec3 facingNormal(vec3 interpolated, vec3 facingGeometric) {
    vec3 n = interpolated;
    if (!(dot(n, n) > 1e-24)) n = facingGeometric;
    n = normalize(n);
    return dot(n, facingGeometric) < 0.0 ? -n : n;
}

// The texture's colour alone (white without a texture) times the vertex colour, and the full
// alpha (material × texel),
// with explicit texture derivatives, for passes without screen-space derivatives (voxelization
// samples at a clipped-polygon centroid; the material's colour factor is applied later, by
// index, so that changing it needs no new voxelization). Does not discard: the caller decides.
vec4 materialTextureGrad(vec2 uv, vec2 dUvdx, vec2 dUvdy, vec3 vertexColor) {
    vec4 texel = uHasTexture != 0 ? textureGrad(uBaseColorTexture, uv, dUvdx, dUvdy) : vec4(1.0);
    return vec4(texel.rgb * materialVertexColor(vertexColor), texel.a * uBaseColor.a);
}

bool materialCutsAway(float alpha) { return uAlphaCutoff >= 0.0 && alpha < uAlphaCutoff; }
