// Shadow lookup in a light-view map with reversed depth (nearest surface = largest depth).
// Requires lights.glsl.
layout(binding = TEXTURE_SHADOW_MAP) uniform sampler2DShadow uShadowMap;  // compare mode GL_GEQUAL: 1 where ref ≥ stored (lit)
uniform mat4 uLightViewProjection;
uniform float uShadowTexelSize;      // texel edge in metres (directional) or at distance 1 (spot)
uniform int uShadowPerspective;
uniform int uPcfRadius;              // taps per side = 2r + 1 (where the pixel is narrower)

// Pair `pair` (0..r) of the PCF filter along one axis (shadowVisibility): the offset of its
// bilinear comparison from the pair's first texel, and its weight.
vec2 shadowTapPair(int pair, int radius, float f) {
    float a = pair == 0 ? 1.0 - f : 1.0, b = pair == radius ? f : 1.0;
    return vec2(b / (a + b), a + b);
}

// `p` in the map's texel coordinates (texel centres at integers) and its depth.
vec3 shadowMapPoint(vec3 p, vec2 size) {
    vec4 clip = uLightViewProjection * vec4(p, 1.0);
    vec3 ndc = clip.xyz / clip.w;
    return vec3((ndc.xy * 0.5 + 0.5) * size - 0.5, ndc.z);
}

// Receiver-plane depth: how the depth of the receiving surface (the plane through the point with
// normal `n`) changes per texel of the map, found by projecting two steps along the plane. Each
// filter tap then compares the depth the surface has at that tap, not at the point, so a surface
// lit at a grazing angle does not shadow itself across the filter. Clamped to `limit` per texel:
// a plane edge-on to the light has no finite slope.
vec2 receiverDepthSlope(vec3 p, vec3 n, float step, vec3 centre, vec2 size, float limit) {
    vec3 tangent, bitangent;
    orthonormalBasis(n, tangent, bitangent);
    vec3 d1 = shadowMapPoint(p + tangent * step, size) - centre;
    vec3 d2 = shadowMapPoint(p + bitangent * step, size) - centre;
    float det = d1.x * d2.y - d2.x * d1.y;
    if (!(abs(det) > 1e-6)) return vec2(0.0);
    vec2 slope = vec2(d1.z * d2.y - d2.z * d1.y, d2.z * d1.x - d1.z * d2.x) / det;
    return clamp(slope, vec2(-limit), vec2(limit));
}

// Fraction of the light that reaches `p` (0 = fully shadowed). Acne is kept away by following
// the receiving plane's depth across the filter (receiverDepthSlope), with a margin of one texel
// of that slope (a bilinear comparison spans a texel around its tap, where the plane's depth
// differs by up to that much), and by pushing the point a texel towards the light and a quarter
// texel off the surface (interpolated normals differ from the true surface). The push along the
// normal stays small on purpose: it moves the lookup sideways in the map, and at grazing light
// a sideways texel moves the shadow edge of an overhang along the wall by several texels.
// Everything scales with the texel, so it works at any scene scale.
// `spanX`, `spanY`: the pixel sample's footprint on the surface, the parallelogram of ±½ of each
// (world units; both 0 for none). Where it covers more of the map than the filter's 2r + 1 texels (a
// map finer than the pixel would otherwise alias its shadow edges), the filter becomes a grid of
// bilinear comparisons over it instead, each at the depth the surface has there.
float shadowVisibility(vec3 p, vec3 n, vec3 toLight, float distanceToLight, vec3 spanX, vec3 spanY) {
    float texel = uShadowTexelSize * (uShadowPerspective != 0 ? distanceToLight : 1.0);
    vec3 offsetPoint = p + n * (0.25 * texel) + toLight * texel;
    if ((uLightViewProjection * vec4(offsetPoint, 1.0)).w <= 0.0) return 0.0;  // behind a spot light
    vec2 size = vec2(textureSize(uShadowMap, 0));
    vec3 centre = shadowMapPoint(offsetPoint, size);
    if (any(lessThan(centre.xy, vec2(-0.5))) || any(greaterThan(centre.xy, size - 0.5))) return 1.0;
    // The depth of one texel along the light: the scale of the slope's limit (32 texels of depth
    // per texel, about 88° from the light, where a surface receives 3 % of the light).
    float texelDepth = abs(shadowMapPoint(offsetPoint + toLight * texel, size).z - centre.z);
    vec2 slope = receiverDepthSlope(offsetPoint, n, texel, centre, size, 32.0 * texelDepth);
    float margin = abs(slope.x) + abs(slope.y);
    float filterTexels = float(2 * uPcfRadius + 1);
    if (spanX != vec3(0.0)) {
        vec3 mapX = shadowMapPoint(offsetPoint + spanX, size) - centre;
        vec3 mapY = shadowMapPoint(offsetPoint + spanY, size) - centre;
        float extent = max(length(mapX.xy), length(mapY.xy));
        if (extent > filterTexels) {
            // cells × cells comparisons at the centres of as many cells of the footprint, about
            // three texels apart up to 5 × 5 (finer grids changed no measured image; a wider PCF
            // keeps its 2r + 1), each blurred by its bilinear tent.
            int cells = max(min(int(ceil(extent / 3.0)), 5), 2 * uPcfRadius + 1);
            float lit = 0.0;
            for (int y = 0; y < cells; ++y)
                for (int x = 0; x < cells; ++x) {
                    vec2 cell = (vec2(x, y) + 0.5) / float(cells) - 0.5;
                    vec3 at = centre + cell.x * mapX + cell.y * mapY;
                    lit += texture(uShadowMap, vec3((at.xy + 0.5) / size, at.z + margin));
                }
            return lit / float(cells * cells);
        }
    }
    // The filter: (2r + 1)² bilinear comparisons one texel apart, a box of 2r + 1 texels blurred
    // by the bilinear tent. Per axis that weighs the 2r + 2 texels around the point 1 − f, 1, …,
    // 1, f (f the point's fraction between texel centres); taken in pairs of neighbouring texels,
    // each pair is one bilinear comparison placed between them in proportion to their weights, so
    // (r + 1)² lookups give the same filter as (2r + 1)².
    float taps = filterTexels * filterTexels;
    vec2 first = floor(centre.xy) - float(uPcfRadius), f = centre.xy - floor(centre.xy);
    float lit = 0.0;
    for (int y = 0; y <= uPcfRadius; ++y) {
        vec2 yPair = shadowTapPair(y, uPcfRadius, f.y);
        for (int x = 0; x <= uPcfRadius; ++x) {
            vec2 xPair = shadowTapPair(x, uPcfRadius, f.x);
            vec2 at = first + 2.0 * vec2(x, y) + vec2(xPair.x, yPair.x);
            float surfaceDepth = centre.z + dot(slope, at - centre.xy) + margin;
            lit += xPair.y * yPair.y * texture(uShadowMap, vec3((at + 0.5) / size, surfaceDepth));
        }
    }
    return lit / taps;
}
