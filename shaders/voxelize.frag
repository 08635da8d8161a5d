#version 450
// Voxelization, fragment stage: for one pixel column of the dominant-axis projection, clip the
// triangle to the pixel's square exactly, find the depth range it spans there, and append one
// voxel fragment per cell of that range (closed cells: touching a cell's face counts, so the set
// contains every cell the triangle touches). Each fragment carries the surface area the triangle
// has inside its cell: the column's share, split along depth in proportion to the overlap; a
// triangle flat on a cell face (no depth range) gives all of it to the cell its plane starts,
// the other keeping an empty fragment (occupied, nothing in it), so that it stays one layer
// thick. A triangle crossing cells in depth also gives each of them the coverage of the whole
// column, as what it blocks along the projection axis: a ray along the column meets the
// triangle in one of those cells, whichever, where with the area split between two cells each
// would let half through, a quarter in all (a tilted wall, a vault, would leak light).
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
// Per fragment: cell (with where the triangle continues in its column above packCell's bits,
// voxel_common.glsl), texture × vertex colour RGB8 with the column coverage in the top byte
// (packColumnCoverage; the material's colour factor and emission are applied by svo_leaves), the
// triangle's normal (octahedral), material index << 16 | area (half float).
layout(rgba32ui, binding = IMAGE_FRAGMENTS) uniform writeonly uimageBuffer uFragments;

uniform uint uCapacity;
uniform int uResolution;

const float kEps = 1e-4;  // voxels; keeps the coverage conservative under float rounding

uvec3 unproject(uvec3 c, int axis) {
    if (axis == 0) return c.zxy;  // projected (y, z, x)
    if (axis == 1) return c.yzx;  // projected (z, x, y)
    return c;
}

// The part of the segment a + t·(b − a), t in [tLow, tHigh], where s0 + t·(s1 − s0) ≥ 0.
void clipInterval(float s0, float s1, inout float tLow, inout float tHigh) {
    if (s1 == s0) {
        if (s0 < 0.0) tHigh = -1.0;  // wholly outside
        return;
    }
    const float t = s0 / (s0 - s1);
    if (s1 > s0)
        tLow = max(tLow, t);
    else
        tHigh = min(tHigh, t);
}

// The clipped polygon (triangle ∩ pixel square) is never built: its boundary is the parts of the
// triangle's edges inside the square and the parts of the square's edges inside the triangle, each
// found as a parameter interval (Liang–Barsky). Green's theorem sums the area over those pieces;
// their end points are the polygon's vertices, which give its depth range and a point inside it.
// Fixed loops without arrays indexed at run time: llvmpipe runs them several times faster than
// Sutherland–Hodgman clipping into a local array.
struct Boundary {
    float twiceArea;  // Σ cross(a, b) over the boundary's pieces (counter-clockwise: positive)
    vec2 endSum;      // Σ (a + b): twice the sum of the polygon's vertices
    float pieces;
    float wLow, wHigh;
    bool touched;     // some piece of boundary lies in the square
};

void addPiece(inout Boundary boundary, vec3 a, vec3 b) {
    const float cross2 = a.x * b.y - b.x * a.y;
    boundary.twiceArea += cross2;
    boundary.endSum += a.xy + b.xy;
    boundary.pieces += 1.0;
    boundary.wLow = min(boundary.wLow, min(a.z, b.z));
    boundary.wHigh = max(boundary.wHigh, max(a.z, b.z));
    boundary.touched = true;
}

void main() {
    const vec2 pixel = floor(gl_FragCoord.xy);
    const vec2 lo = pixel - kEps, hi = pixel + 1.0 + kEps;
    // Counter-clockwise, like the square, so that both kinds of piece add with the same sign.
    vec3 t0 = gTri0, t1 = gTri1, t2 = gTri2;
    const float orientation = (t1.x - t0.x) * (t2.y - t0.y) - (t1.y - t0.y) * (t2.x - t0.x);
    if (orientation < 0.0) {
        const vec3 swap = t1;
        t1 = t2;
        t2 = swap;
    }
    const vec3 tri[3] = vec3[3](t0, t1, t2);
    Boundary boundary = Boundary(0.0, vec2(0.0), 0.0, 1e30, -1e30, false);

    // The triangle's edges, clipped to the square.
    for (int i = 0; i < 3; ++i) {
        const vec3 a = tri[i], b = tri[(i + 1) % 3];
        float tLow = 0.0, tHigh = 1.0;
        clipInterval(a.x - lo.x, b.x - lo.x, tLow, tHigh);
        clipInterval(hi.x - a.x, hi.x - b.x, tLow, tHigh);
        clipInterval(a.y - lo.y, b.y - lo.y, tLow, tHigh);
        clipInterval(hi.y - a.y, hi.y - b.y, tLow, tHigh);
        if (tLow <= tHigh) addPiece(boundary, mix(a, b, tLow), mix(a, b, tHigh));
    }
    // The square's edges, clipped to the triangle (a degenerate triangle has no inside). Depth
    // along them comes from the triangle's plane, kept within its vertices' depths (which bound
    // every point of the triangle) against rounding in needle-thin ones.
    if (orientation != 0.0) {
        const vec2 corners[4] = vec2[4](vec2(lo.x, lo.y), vec2(hi.x, lo.y), vec2(hi.x, hi.y), vec2(lo.x, hi.y));
        const vec2 e1 = t1.xy - t0.xy, e2 = t2.xy - t0.xy;
        const float invDet = 1.0 / (e1.x * e2.y - e1.y * e2.x);
        for (int i = 0; i < 4; ++i) {
            const vec2 a = corners[i], b = corners[(i + 1) % 4];
            float tLow = 0.0, tHigh = 1.0;
            for (int k = 0; k < 3; ++k) {
                const vec2 p = tri[k].xy, q = tri[(k + 1) % 3].xy;
                const vec2 edge = q - p;
                clipInterval(edge.x * (a.y - p.y) - edge.y * (a.x - p.x), edge.x * (b.y - p.y) - edge.y * (b.x - p.x),
                             tLow, tHigh);
            }
            if (tLow >= tHigh) continue;  // only a corner touches the triangle: no length, no area
            vec3 pieceStart = vec3(mix(a, b, tLow), 0.0), pieceEnd = vec3(mix(a, b, tHigh), 0.0);
            for (int end = 0; end < 2; ++end) {
                const vec2 r = (end == 0 ? pieceStart.xy : pieceEnd.xy) - t0.xy;
                const float s = (r.x * e2.y - r.y * e2.x) * invDet, t = (e1.x * r.y - e1.y * r.x) * invDet;
                const float w = clamp(t0.z + s * (t1.z - t0.z) + t * (t2.z - t0.z), min(min(t0.z, t1.z), t2.z),
                                      max(max(t0.z, t1.z), t2.z));
                if (end == 0) pieceStart.z = w; else pieceEnd.z = w;
            }
            addPiece(boundary, pieceStart, pieceEnd);
        }
    }
    if (!boundary.touched) discard;  // the enlarged primitive covered a pixel the triangle misses

    // Coverage (projected area), the mean of the clipped polygon's vertices (inside it: it is
    // convex) and its depth range.
    const float coverage = max(boundary.twiceArea * 0.5, 0.0);
    const vec2 polygonCentre = boundary.endSum / (2.0 * boundary.pieces);
    const float wLow = boundary.wLow, wHigh = boundary.wHigh;

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
    int planeCell = clamp(int(floor(0.5 * (wLow + wHigh))), first, last);
    // Within one cell (or flat in one) the area already says what the cell blocks.
    float columnCoverage = span > 1e-6 && last > first ? coverage : 0.0;
    uint colour = packUnorm4x8(vec4(clamp(base.rgb, 0.0, 1.0), 0.0));
    uint packedNormal = packNormal(gFaceNormal);
    for (int k = first; k <= last; ++k) {
        float share = span > 1e-6 ? max(min(wHigh, float(k + 1)) - max(wLow, float(k)), 0.0) / span
                                  : (k == planeCell ? 1.0 : 0.0);
        float area = coverage * gAreaScale * share;
        uvec3 cell = unproject(uvec3(uvec2(pixel), uint(k)), gAxis);
        // A cell the triangle only touches (no share of its depth) blocks nothing of the column.
        uint albedo = colour | (packColumnCoverage(gAxis, share > 0.0 ? columnCoverage : 0.0) << 24);
        uint index = atomicAdd(fragmentCount, 1u);
        if (index < uCapacity) {
            uint materialAndArea = (uint(uMaterialIndex) << 16) | (packHalf2x16(vec2(area, 0.0)) & 0xFFFFu);
            uint columnPlace = (wLow < float(k) ? COLUMN_CONTINUES_BELOW : 0u) | (wHigh > float(k + 1) ? COLUMN_CONTINUES_ABOVE : 0u);
            imageStore(uFragments, int(index), uvec4(packCell(cell) | columnPlace, albedo, packedNormal, materialAndArea));
        }
    }
}
