// The near field of a pixel's narrow cones (SCREEN_NEAR_FIELD): a cone starts uConeOffset voxels
// off the surface, so what lies nearer than that along its axis (a curtain's hem half a voxel
// above a sunlit floor, the other face of a crease) neither lights nor shades the pixel through
// it. Before a cone is traced, its axis is followed as a ray from the pixel's surface point up to
// where the cone starts, against the G-buffer: where it passes behind a surface the camera sees,
// the ray has met that surface, and its radiance (direct light and emission, what the first
// bounce sends) takes the cone's place, fully opaque. A surface met from the side the camera does
// not see (the sunlit face of a column or a curtain fold seen from behind, the inside of an arch)
// sends light the G-buffer does not hold: the voxels there say what it sends back along the axis
// (hiddenSideLight, defined by the includer), or it only blocks. What the camera does not see
// (off screen, hidden) leaves the cone as it was.
// Requires uVoxelScale, uConeOffset, the G-buffer samplers uPosition and uGeometricNormal
// (cone_trace_common.glsl), and
//   bool hiddenSideLight(vec3 point, vec3 normal, vec3 direction, float length, out vec3 radiance):
// the light that the surface met within about `length` (scene units) of `point` along
// `direction` sends back towards it, where it knows it (cone_march.glsl, from the voxels). The
// ray is stopped up to a step before the surface: the length asked reaches a step past it.
layout(binding = TEXTURE_NEAR_FIELD_DIRECT) uniform sampler2D uNearFieldDirect;
layout(binding = TEXTURE_NEAR_FIELD_EMISSIVE) uniform sampler2D uNearFieldEmissive;
uniform mat4 uViewProjection;  // scene-local to clip space, as the G-buffer was rasterized
uniform vec3 uEye;             // scene-local

// The pixel whose cones are gathered (gatherPixel sets them).
vec3 nearFieldPoint = vec3(0.0), nearFieldNormal = vec3(0.0, 0.0, 1.0);
float nearFieldJitter = 0.5;

// Steps along the axis; near_detail.comp, which follows many directions at every pixel, takes fewer.
#ifndef NEAR_FIELD_STEPS
#define NEAR_FIELD_STEPS 6
#endif

bool nearFieldHit(vec3 direction, out vec4 seen) {
    seen = vec4(0.0);
    const float voxel = 1.0 / uVoxelScale;  // scene-local units per voxel
    const float cosine = dot(direction, nearFieldNormal);
    // Along the axis to the height where the cone starts; at a grazing angle no further than
    // three times that.
    const float reach = uConeOffset * voxel / max(cosine, 1.0 / 3.0);
    const float step = reach / float(NEAR_FIELD_STEPS);
    const vec2 size = vec2(textureSize(uPosition, 0));
    // Clip space is linear along the ray: two products instead of one per step.
    const vec4 clipOrigin = uViewProjection * vec4(nearFieldPoint, 1.0);
    const vec4 clipDirection = uViewProjection * vec4(direction, 0.0);
    for (int i = 0; i < NEAR_FIELD_STEPS; ++i) {
        const float t = reach * (float(i) + nearFieldJitter) / float(NEAR_FIELD_STEPS);
        const vec3 q = nearFieldPoint + direction * t;
        const vec4 clip = clipOrigin + clipDirection * t;
        if (!(clip.w > 0.0)) return false;
        const vec2 at = (clip.xy / clip.w * 0.5 + 0.5) * size;
        if (any(lessThan(at, vec2(0.0))) || any(greaterThanEqual(at, size))) return false;
        const ivec2 texel = ivec2(at);
        const vec4 surface = texelFetch(uPosition, texel, 0);
        if (!(surface.w > 0.0)) continue;  // sky
        // Only a surface in front of the pixel's own plane, which q has just crossed: q lies
        // behind the surface's plane by at most a step (measured across the plane: a wall seen
        // at a grazing angle hides points far along the view ray but close behind it), and
        // not far behind it along the view ray (q passes behind something nearer the camera).
        if (dot(surface.xyz - nearFieldPoint, nearFieldNormal) < 0.1 * voxel) continue;
        const vec3 surfaceNormal = texelFetch(uGeometricNormal, texel, 0).xyz;
        const float behindPlane = dot(surface.xyz - q, surfaceNormal);
        const float behindAlongView = distance(q, uEye) - distance(surface.xyz, uEye);
        if (behindPlane < 0.05 * voxel || behindPlane > step + 0.1 * voxel || behindAlongView > reach) continue;
        seen.a = 1.0;
        vec3 hidden;
        if (dot(surfaceNormal, direction) < 0.0)
            seen.rgb = texelFetch(uNearFieldDirect, texel, 0).rgb + texelFetch(uNearFieldEmissive, texel, 0).rgb;
        else if (hiddenSideLight(nearFieldPoint, nearFieldNormal, direction, t + step, hidden))
            seen.rgb = hidden;
        return true;
    }
    return false;
}
