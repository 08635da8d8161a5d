#version 450
layout(local_size_x = 8, local_size_y = 8) in;
// indirect_filter (render/indirect_filter.hpp): one pass of an edge-aware à-trous filter of the
// cones' irradiance, on the image cone_trace.comp traced (every pixel, or one pixel of each 2×2
// block, whose G-buffer point the cell stands for). Each pass fits a plane to a 3×3 kernel of taps
// uTapSpacing cells apart (weights ¼ ½ ¼ per axis), each tap weighted by how far its surface point
// lies from this cell's (a Gaussian of uSigma voxels), how alike the normals are and how far it
// lies off this cell's tangent plane; the cell takes the plane's value at its centre. Successive
// passes double the spacing, so a few of them reach far at 9 taps each; the Gaussian in voxels,
// not the reach in cells, sets the width.
//
// Why a plane and not the weighted mean: near an edge of the image or of its surface a cell has
// taps on one side only, and their mean is the value half a kernel inwards. Irradiance changes
// across a surface (it darkens into a corner, brightens towards a sunlit strip), so the mean would
// move light from the middle of each surface to its edges; the plane keeps a linear change where
// it is, on whichever side the taps lie.
#include "traced_pixel.glsl"

layout(binding = TEXTURE_GBUFFER_NORMAL) uniform sampler2D uNormal;
layout(binding = TEXTURE_GBUFFER_POSITION) uniform sampler2D uPosition;
layout(binding = TEXTURE_TRACED_IRRADIANCE) uniform sampler2D uIrradiance;
layout(binding = TEXTURE_TRACED_PIXEL) uniform usampler2D uTracedPixel;  // with uDownscale > 1
layout(rgba32f, binding = IMAGE_INDIRECT) uniform writeonly image2D uFiltered;

uniform int uDownscale;     // 1: a cell is its pixel; > 1: uTracedPixel says which pixel it traced
uniform int uTapSpacing;    // in cells
uniform float uVoxelScale;  // voxels per world unit
uniform float uSigma;       // voxels

// A tap two voxels off the tangent plane keeps e⁻¹ of its weight (sameSurfaceWeight).
const float kPlaneVoxels = 2.0;
const float kTapWeight[2] = float[2](0.5, 0.25);
// The slope is damped by this share of the taps' weight (ridge regression): with few taps, or
// taps along one line, the fit falls back towards their mean instead of extrapolating noise.
const float kSlopeDamping = 0.1;

#include "traced_cell.glsl"

void main() {
    const ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
    const ivec2 size = imageSize(uFiltered);
    if (any(greaterThanEqual(cell, size))) return;
    ivec2 pixel;
    vec3 position, normal;
    const vec4 own = texelFetch(uIrradiance, cell, 0);
    if (!pointOf(cell, pixel, position, normal)) {  // sky: nothing to filter
        imageStore(uFiltered, cell, own);
        return;
    }
    const float inverseTwoSigma2 = 0.5 / (uSigma * uSigma);
    // Weighted least squares of value = a + b·dx + c·dy over the taps: the sums of w·x·xᵀ and
    // w·x·value for x = (1, dx, dy), the cell's own tap included.
    float s00 = 0.0, s01 = 0.0, s02 = 0.0, s11 = 0.0, s12 = 0.0, s22 = 0.0;
    vec4 b0 = vec4(0.0), b1 = vec4(0.0), b2 = vec4(0.0);
    vec4 lowest = own, highest = own;
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            const ivec2 tap = cell + ivec2(dx, dy) * uTapSpacing;
            ivec2 tapPixel;
            vec3 tapPosition, tapNormal;
            if (any(lessThan(tap, ivec2(0))) || any(greaterThanEqual(tap, size)) ||
                !pointOf(tap, tapPixel, tapPosition, tapNormal))
                continue;
            const vec3 offset = (tapPosition - position) * uVoxelScale;
            const float w = kTapWeight[abs(dx)] * kTapWeight[abs(dy)] * exp(-dot(offset, offset) * inverseTwoSigma2) *
                            sameSurfaceWeight(normal, tapNormal, offset, kPlaneVoxels);
            const vec4 value = texelFetch(uIrradiance, tap, 0);
            const float x = float(dx), y = float(dy);
            s00 += w; s01 += w * x; s02 += w * y; s11 += w * x * x; s12 += w * x * y; s22 += w * y * y;
            b0 += w * value; b1 += w * x * value; b2 += w * y * value;
            if (w > 1e-3) {
                lowest = min(lowest, value);
                highest = max(highest, value);
            }
        }
    }
    s11 += kSlopeDamping * s00;
    s22 += kSlopeDamping * s00;
    // a, the plane at the cell, by Cramer's rule (the damped system is positive definite).
    const float c00 = s11 * s22 - s12 * s12, c01 = s02 * s12 - s01 * s22, c02 = s01 * s12 - s11 * s02;
    const vec4 fitted = (c00 * b0 + c01 * b1 + c02 * b2) / (s00 * c00 + s01 * c01 + s02 * c02);
    // A plane never leaves the range of the taps it fits: no overshoot past what the cones gave.
    imageStore(uFiltered, cell, clamp(fitted, lowest, highest));
}
