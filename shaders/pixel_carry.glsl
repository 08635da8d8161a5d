// Indirect light carried over camera moves (render/cone_carry.hpp): which pixel of the last frame's
// indirect image serves a pixel of this one (cone_carry.comp finds it for every pixel, decides
// from it which cells to trace and records it for cone_upsample.comp, which takes the light).
//
// The irradiance a surface point receives does not depend on the camera. A pixel of the last frame
// serves a pixel of this one when the point its light was estimated at lies on the surface this
// pixel sees: within kCarryPlaneVoxels of its tangent plane (nothing stands in front of it), facing
// the same way (normals within uCarryCos), and within uCarryVoxels plus this pixel's footprint on
// the surface of this pixel's point (the last frame's pixels are about a pixel apart there). Light
// keeps the point it was estimated at, so it never stands for light farther than that from where
// it was estimated, and it is carried for at most a few frames (carryFramesAt).

#include "carried_light.glsl"

uniform mat4 uCarriedViewProjection;  // the last frame's camera
uniform mat4 uViewProjection;         // this frame's
uniform vec3 uEye;                    // this frame's, scene-local
uniform float uPixelAngle;            // this frame's pixel footprint per unit of distance
uniform float uCarryVoxels;
uniform float uCarryCos;
uniform float uCarryScale;            // voxels per world unit
uniform int uCarryFrames;             // the most frames light is carried (kConeCarryFrames)

const float kCarryPlaneVoxels = 0.25;

// How many frames the light estimated at `point` is carried at most: from half of uCarryFrames to
// all of it, by a hash of its voxel, so that a view's light does not all expire in one frame.
int carryFramesAt(vec3 point) {
    uvec3 v = uvec3(ivec3(floor(point * uCarryScale)));
    uint h = v.x * 73856093u ^ v.y * 19349663u ^ v.z * 83492791u;
    h ^= h >> 16; h *= 0x7feb352du; h ^= h >> 15;
    const int half_ = max(uCarryFrames / 2, 1);
    return half_ + int(h % uint(uCarryFrames - half_ + 1));
}

// The last frame's pixel that serves this frame's surface point `position` (normal `normal`): of
// the 3×3 pixels around where the last camera saw it, the one whose light belongs nearest; (-1, -1)
// if none does.
ivec2 carriedPixelFor(vec3 position, vec3 normal) {
    if (uCarry == 0) return ivec2(-1);
    const vec4 clip = uCarriedViewProjection * vec4(position, 1.0);
    if (!(clip.w > 0.0)) return ivec2(-1);
    const ivec2 size = textureSize(uCarriedAt, 0);
    const ivec2 around = ivec2(floor((clip.xy / clip.w * 0.5 + 0.5) * vec2(size)));
    // A pixel's footprint: its angle times the distance along the camera's axis, stretched by the
    // slant at which the surface is seen (up to 4×): at a grazing angle the last frame's pixels lie
    // farther apart on the surface.
    const float depth = (uViewProjection * vec4(position, 1.0)).w;
    const float slant = max(abs(dot(normal, normalize(uEye - position))), 0.25);
    const float reach = uCarryVoxels + depth * uPixelAngle / slant * uCarryScale;
    ivec2 best = ivec2(-1);
    vec4 bestAt = vec4(0.0);
    float bestDistance = reach;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const ivec2 from = around + ivec2(dx, dy);
            if (any(lessThan(from, ivec2(0))) || any(greaterThanEqual(from, size))) continue;
            const vec4 at = texelFetch(uCarriedAt, from, 0);
            if (at.w <= 0.0) continue;
            const vec3 fromNormal = texelFetch(uCarriedNormal, from, 0).xyz;
            if (dot(fromNormal, normal) < uCarryCos) continue;
            const vec3 offset = (position - at.xyz) * uCarryScale;
            const float distance = length(offset);
            if (abs(dot(offset, fromNormal)) <= kCarryPlaneVoxels && distance <= bestDistance) {
                bestDistance = distance;
                best = from;
                bestAt = at;
            }
        }
    // Light carried as long as its point allows is estimated anew, even where a neighbour's could
    // stand in for it: otherwise the neighbours' light would go on in its place.
    if (best.x >= 0 && bestAt.w > float(carryFramesAt(bestAt.xyz))) return ivec2(-1);
    return best;
}
