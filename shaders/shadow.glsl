// Shadow lookup in a light-view map with reversed depth (nearest surface = largest depth).
// Requires lights.glsl.
layout(binding = TEXTURE_SHADOW_MAP) uniform sampler2DShadow uShadowMap;  // compare mode GL_GEQUAL: 1 where ref ≥ stored (lit)
uniform mat4 uLightViewProjection;
uniform float uShadowTexelSize;      // texel edge in metres (directional) or at distance 1 (spot)
uniform int uShadowPerspective;
uniform int uPcfRadius;              // taps per side = 2r + 1

// Pair `pair` (0..r) of the PCF filter along one axis (shadowVisibility): the offset of its
// bilinear comparison from the pair's first texel, and its weight.
vec2 shadowTapPair(int pair, int radius, float f) {
    float a = pair == 0 ? 1.0 - f : 1.0, b = pair == radius ? f : 1.0;
    return vec2(b / (a + b), a + b);
}

// Fraction of the light that reaches `p` (0 = fully shadowed). The point is pushed off the
// surface along its normal and towards the light by about a texel: that removes acne without a
// depth bias tuned per scene, and it scales with the texel, so it works at any scene scale.
float shadowVisibility(vec3 p, vec3 n, vec3 toLight, float distanceToLight) {
    float texel = uShadowTexelSize * (uShadowPerspective != 0 ? distanceToLight : 1.0);
    // Slope-scaled: at grazing light one texel of the map spans a long stretch of the surface and
    // the depth changes a lot across it, so the push off the surface grows with tanθ (capped).
    float cosTheta = clamp(dot(n, toLight), 0.05, 1.0);
    float slope = min(sqrt(1.0 - cosTheta * cosTheta) / cosTheta, 4.0);
    vec3 offsetPoint = p + n * (texel * (1.0 + 0.5 * slope)) + toLight * texel;
    vec4 clip = uLightViewProjection * vec4(offsetPoint, 1.0);
    if (clip.w <= 0.0) return 0.0;
    vec3 ndc = clip.xyz / clip.w;
    vec2 uv = ndc.xy * 0.5 + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return 1.0;
    // The filter: (2r + 1)² bilinear comparisons one texel apart, a box of 2r + 1 texels blurred
    // by the bilinear tent. Per axis that weighs the 2r + 2 texels around the point 1 − f, 1, …,
    // 1, f (f the point's fraction between texel centres); taken in pairs of neighbouring texels,
    // each pair is one bilinear comparison placed between them in proportion to their weights, so
    // (r + 1)² lookups give the same filter as (2r + 1)².
    vec2 size = vec2(textureSize(uShadowMap, 0));
    vec2 texelPoint = uv * size - 0.5;  // texel centres at integers
    vec2 first = floor(texelPoint) - float(uPcfRadius), f = texelPoint - floor(texelPoint);
    float lit = 0.0;
    for (int y = 0; y <= uPcfRadius; ++y) {
        vec2 yPair = shadowTapPair(y, uPcfRadius, f.y);
        for (int x = 0; x <= uPcfRadius; ++x) {
            vec2 xPair = shadowTapPair(x, uPcfRadius, f.x);
            vec2 at = first + 2.0 * vec2(x, y) + vec2(xPair.x, yPair.x);
            lit += xPair.y * yPair.y * texture(uShadowMap, vec3((at + 0.5) / size, ndc.z));
        }
    }
    float taps = float((2 * uPcfRadius + 1) * (2 * uPcfRadius + 1));
    return lit / taps;
}
