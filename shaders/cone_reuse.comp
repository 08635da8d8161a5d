#version 450
layout(local_size_x = 8, local_size_y = 8) in;
// cone_reuse (render/cone_reuse.hpp; when: reusesCones in render/cone_trace.hpp): each traced cell's irradiance from the narrow
// cones of the traced cells around it as well as its own, before the edge-aware filter.
//
// A narrow cone brings back the light that arrives along its axis near its apex. A neighbour's
// cone, whose apex lies a voxel or two away on the same side of both surfaces, saw nearly the
// same light along that direction, whatever the neighbour's normal; so a cell counts every cone of
// its window that points into its own hemisphere, weighted by its own cosine and divided by the
// density with which the whole window drew that direction (multiple importance sampling with the
// balance heuristic: every cell draws N cosine-distributed axes around its normal n_i):
//
//     E = Σ_j Σ_k w_j L_jk cos_p(ω_jk) / Σ_i w_i N cos_i(ω_jk) / π,
//
// w the cells' weights (a Gaussian of their points' distance). The cell alone gives its own
// estimate, π/N Σ_k L_k. The edge-aware filter after it averages irradiance over one surface only;
// sharing directions also averages across the small surfaces it must keep apart (a column's
// flutes, a moulding), where four cones per cell leave the most noise. Where the neighbours' apexes
// see their surroundings differently (a thin surface under another one), it is biased: that is why
// the window stays small.
#include "math.glsl"
#include "traced_pixel.glsl"

layout(binding = TEXTURE_GBUFFER_NORMAL) uniform sampler2D uNormal;
layout(binding = TEXTURE_GBUFFER_GEOMETRIC_NORMAL) uniform sampler2D uGeometricNormal;
layout(binding = TEXTURE_GBUFFER_POSITION) uniform sampler2D uPosition;
layout(binding = TEXTURE_TRACED_IRRADIANCE) uniform sampler2D uTraced;
layout(binding = TEXTURE_TRACED_PIXEL) uniform usampler2D uTracedPixel;  // with uDownscale > 1
// Per traced cell and cone (cone_march.glsl, storeConeSample): (premultiplied radiance, opacity),
// then (axis, 1 if traced, 0 if it lay behind its triangle's plane).
layout(std430, binding = SSBO_CONE_SAMPLES) readonly buffer ConeSamples { vec4 coneSamples[]; };
layout(rgba32f, binding = IMAGE_INDIRECT) uniform writeonly image2D uReused;

uniform int uDownscale;
uniform int uRayCount;
uniform float uVoxelScale;   // voxels per world unit
uniform float uConeOffset;   // the cones' start off their surface, in voxels
uniform float uReuseVoxels;  // σ of the cells' weights over their points' distance, in voxels

#include "traced_cell.glsl"

const int kWindow = (2 * REUSE_RADIUS + 1) * (2 * REUSE_RADIUS + 1);

void main() {
    const ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
    const ivec2 size = imageSize(uReused);
    if (any(greaterThanEqual(cell, size))) return;
    ivec2 pixel;
    vec3 position, normal;
    if (!pointOf(cell, pixel, position, normal) || carriedCell(cell)) {  // sky, or carried light: no cones
        imageStore(uReused, cell, texelFetch(uTraced, cell, 0));
        return;
    }
    const vec3 geometric = texelFetch(uGeometricNormal, pixel, 0).xyz;

    // The window: the cell itself, and each neighbour whose apex lies in front of this cell's
    // triangle while this cell's apex lies in front of the neighbour's (no surface between them
    // to see through).
    int cells[kWindow];
    float weights[kWindow];
    vec3 normals[kWindow], geometrics[kWindow];
    int count = 0;
    const float inverseTwoSigma2 = 0.5 / (uReuseVoxels * uReuseVoxels);
    for (int dy = -REUSE_RADIUS; dy <= REUSE_RADIUS; ++dy)
        for (int dx = -REUSE_RADIUS; dx <= REUSE_RADIUS; ++dx) {
            const ivec2 q = cell + ivec2(dx, dy);
            ivec2 qPixel;
            vec3 qPosition, qNormal;
            if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size)) || !pointOf(q, qPixel, qPosition, qNormal) ||
                carriedCell(q))
                continue;
            const vec3 qGeometric = texelFetch(uGeometricNormal, qPixel, 0).xyz;
            const vec3 offset = (qPosition - position) * uVoxelScale;
            const bool self = dx == 0 && dy == 0;
            const float weight = exp(-dot(offset, offset) * inverseTwoSigma2);  // 1 for the cell itself
            if (!self && (weight < 1e-3 || dot(offset + qNormal * uConeOffset, geometric) < 0.5 ||
                          dot(normal * uConeOffset - offset, qGeometric) < 0.5))
                continue;
            cells[count] = q.y * size.x + q.x;
            weights[count] = weight;
            normals[count] = qNormal;
            geometrics[count] = qGeometric;
            ++count;
        }

    // A cone traced behind its own triangle's plane was not drawn there (the triangle blocks it);
    // a direction behind this cell's triangle brings it nothing and blocks it.
    const float drawnDensity = float(uRayCount) / PI;
    vec4 sum = vec4(0.0);  // irradiance, Σ opacity·cosθ dω
    for (int i = 0; i < count; ++i)
        for (int k = 0; k < uRayCount; ++k) {
            const int at = 2 * (cells[i] * uRayCount + k);
            const vec4 axis = coneSamples[at + 1];
            const float cosine = dot(axis.xyz, normal);
            if (axis.w == 0.0 || cosine <= 0.0) continue;
            float density = 0.0;
            for (int j = 0; j < count; ++j)
                if (dot(axis.xyz, geometrics[j]) > 0.0) density += weights[j] * drawnDensity * max(dot(axis.xyz, normals[j]), 0.0);
            const vec4 cone = dot(axis.xyz, geometric) > 0.0 ? coneSamples[at] : vec4(0.0, 0.0, 0.0, 1.0);
            sum += (weights[i] * cosine / density) * cone;
        }
    // Weighted by densities, the opacities of other cells' cones can add up past the whole
    // hemisphere where the window drew unevenly: visibility stays in [0, 1], as one cell's own is.
    imageStore(uReused, cell, vec4(sum.rgb, clamp(1.0 - sum.a / PI, 0.0, 1.0)));
}
