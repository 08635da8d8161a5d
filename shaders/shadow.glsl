// Shadow lookup in a light-view map with reversed depth (nearest surface = largest depth).
// Requires lights.glsl.
layout(binding = TEXTURE_SHADOW_MAP) uniform sampler2DShadow uShadowMap;  // compare mode GL_GEQUAL: 1 where ref ≥ stored (lit)
uniform mat4 uLightViewProjection;
uniform float uShadowTexelSize;      // texel edge in metres (directional) or at distance 1 (spot)
uniform int uShadowPerspective;
uniform int uPcfRadius;              // taps per side = 2r + 1

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
    vec2 step = 1.0 / vec2(textureSize(uShadowMap, 0));
    float lit = 0.0;
    for (int y = -uPcfRadius; y <= uPcfRadius; ++y)
        for (int x = -uPcfRadius; x <= uPcfRadius; ++x)
            lit += texture(uShadowMap, vec3(uv + vec2(x, y) * step, ndc.z));
    float taps = float((2 * uPcfRadius + 1) * (2 * uPcfRadius + 1));
    return lit / taps;
}
