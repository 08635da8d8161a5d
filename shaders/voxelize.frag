#version 450
// Voxelization, fragment stage: for one pixel column of the dominant-axis projection, clip the
// triangle to the pixel's square exactly, find the depth range it spans there, and append one
// voxel fragment per cell of that range (closed cells: touching a cell's face counts, so the set
// contains every cell the triangle touches). Each fragment carries the surface area the triangle
// has inside its cell (the column's share, split along depth in proportion to the overlap).
#include "material.glsl"
#include "voxel_common.glsl"

flat in vec3 gTri0;
flat in vec3 gTri1;
flat in vec3 gTri2;
flat in int gAxis;
flat in float gAreaScale;
flat in vec2 gUv0;
flat in vec2 gUv1;
flat in vec2 gUv2;
flat in vec3 gColor0;
flat in vec3 gColor1;
flat in vec3 gColor2;
flat in vec3 gFaceNormal;

layout(std430, binding = SSBO_FRAGMENT_COUNTER) buffer FragmentCounter { uint fragmentCount; };
// Per fragment: cell, texture × vertex colour RGBA8 (the material's colour factor and emission are applied
// by svo_leaves), the triangle's normal (octahedral), material index << 16 | area (half float).
layout(rgba32ui, binding = IMAGE_FRAGMENTS) uniform writeonly uimageBuffer uFragments;

uniform uint uCapacity;
uniform int uResolution;

const float kEps = 1e-4;  // voxels; keeps the coverage conservative under float rounding
const int kMaxPolygon = 9;

// Sutherland–Hodgman against one axis-aligned line: keeps the side where sign·(p[axis] − bound) ≥ 0.
void clipPolygon(inout vec3 poly[kMaxPolygon], inout int count, int axis, float bound, float sign) {
    vec3 result[kMaxPolygon];
    int n = 0;
    for (int i = 0; i < count; ++i) {
        vec3 a = poly[i], b = poly[(i + 1) % count];
        float da = sign * (a[axis] - bound), db = sign * (b[axis] - bound);
        if (da >= 0.0 && n < kMaxPolygon) result[n++] = a;
        if ((da >= 0.0) != (db >= 0.0) && n < kMaxPolygon) result[n++] = mix(a, b, da / (da - db));
    }
    poly = result;
    count = n;
}

uvec3 unproject(uvec3 c, int axis) {
    if (axis == 0) return c.zxy;  // projected (y, z, x)
    if (axis == 1) return c.yzx;  // projected (z, x, y)
    return c;
}

void main() {
    vec2 pixel = floor(gl_FragCoord.xy);
    vec3 poly[kMaxPolygon];
    poly[0] = gTri0;
    poly[1] = gTri1;
    poly[2] = gTri2;
    int count = 3;
    clipPolygon(poly, count, 0, pixel.x - kEps, 1.0);
    clipPolygon(poly, count, 0, pixel.x + 1.0 + kEps, -1.0);
    clipPolygon(poly, count, 1, pixel.y - kEps, 1.0);
    clipPolygon(poly, count, 1, pixel.y + 1.0 + kEps, -1.0);
    if (count == 0) discard;  // the enlarged primitive covered a pixel the triangle misses

    // Coverage (projected area), polygonCentre and depth range of the clipped polygon.
    float coverage = 0.0;
    vec2 polygonCentre = vec2(0.0);
    float wLow = poly[0].z, wHigh = poly[0].z;
    for (int i = 0; i < count; ++i) {
        vec3 a = poly[i], b = poly[(i + 1) % count];
        coverage += a.x * b.y - b.x * a.y;
        polygonCentre += a.xy;
        wLow = min(wLow, a.z);
        wHigh = max(wHigh, a.z);
    }
    coverage = abs(coverage) * 0.5;
    polygonCentre /= float(count);

    // Attributes at the polygonCentre (inside the triangle) through barycentric coordinates, and the
    // texture footprint of one voxel for mip selection.
    vec2 e1 = gTri1.xy - gTri0.xy, e2 = gTri2.xy - gTri0.xy;
    float det = e1.x * e2.y - e1.y * e2.x;
    // A degenerate triangle (segment or point, see voxelize.geom) has no barycentric frame: it
    // takes its first vertex's attributes.
    float invDet = abs(det) > 1e-30 ? 1.0 / det : 0.0;
    vec2 r = polygonCentre - gTri0.xy;
    float s = (r.x * e2.y - r.y * e2.x) * invDet;
    float t = (e1.x * r.y - e1.y * r.x) * invDet;
    // s, t are inside the triangle up to rounding, which in a needle-thin triangle can be large;
    // they are not clamped: a slightly extrapolated uv only shifts a texel, while clamping them
    // makes llvmpipe (Mesa 22.3) run this pass tens of times slower on Sponza.
    vec2 uv = gUv0 + s * (gUv1 - gUv0) + t * (gUv2 - gUv0);
    vec2 dUvdx = (e2.y * (gUv1 - gUv0) - e1.y * (gUv2 - gUv0)) * invDet;
    vec2 dUvdy = (-e2.x * (gUv1 - gUv0) + e1.x * (gUv2 - gUv0)) * invDet;
    vec3 vertexColor = gColor0 + s * (gColor1 - gColor0) + t * (gColor2 - gColor0);
    vec4 base = materialTextureGrad(uv, dUvdx, dUvdy, vertexColor);
    if (materialCutsAway(base.a)) discard;

    int first = max(int(ceil(wLow - kEps)) - 1, 0);
    int last = min(int(floor(wHigh + kEps)), uResolution - 1);
    float span = wHigh - wLow;
    uint albedo = packUnorm4x8(vec4(clamp(base.rgb, 0.0, 1.0), 1.0));
    uint packedNormal = packNormal(gFaceNormal);
    for (int k = first; k <= last; ++k) {
        float share = span > 1e-6 ? max(min(wHigh, float(k + 1)) - max(wLow, float(k)), 0.0) / span
                                  : 1.0 / float(last - first + 1);
        float area = coverage * gAreaScale * share;
        uvec3 cell = unproject(uvec3(uvec2(pixel), uint(k)), gAxis);
        uint index = atomicAdd(fragmentCount, 1u);
        if (index < uCapacity) {
            uint materialAndArea = (uint(uMaterialIndex) << 16) | (packHalf2x16(vec2(area, 0.0)) & 0xFFFFu);
            imageStore(uFragments, int(index), uvec4(packCell(cell), albedo, packedNormal, materialAndArea));
        }
    }
}
