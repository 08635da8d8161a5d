// Diffuse cones marched through the radiance bricks (DESIGN §5.5): the cone set's uniforms and
// traceCone, shared by the pass that gathers per pixel (cone_trace.comp) and the one that gathers
// per voxel for further bounces (bounce_gather.comp). Each cone composites premultiplied
// radiance front to back; its result times its weight (∫cosθ dω of its region, weights sum to π)
// adds up to the irradiance E arriving at the cone set's apex.
#include "math.glsl"
#include "voxel_common.glsl"
#include "octree.glsl"
#include "bricks_common.glsl"
#include "directional_pool.glsl"
#include "octree_march.glsl"
#include "cone_spread.glsl"
#include "cell_radiance.glsl"
#include "facing.glsl"
#include "cone_regions.glsl"
#include "narrow_cone_directions.glsl"

// What lies ahead of each brick sample along each of the six axis directions (brick_layout.hpp,
// "Slabs"; directional_pool.glsl): the radiance that reaches the sample and the slab's density,
// (L·τ, τ); the density of the geometry everywhere, radiance only near light.
layout(binding = TEXTURE_DIRECTIONAL_RADIANCE) uniform sampler3D uDirectional;
// Samples this invocation took, and those empty-space skipping saved (cone_trace counts them).
uint samplesTaken = 0u, samplesSaved = 0u;

uniform int uConeCount;
uniform vec3 uConeDirection[MAX_CONES];  // tangent space, z = normal
uniform float uConeTanHalfAngle[MAX_CONES];
uniform float uConeWeight[MAX_CONES];
uniform float uConeStep;     // step length as a fraction of the cone diameter
uniform float uConeOffset;   // start offset along the normal, in voxels
uniform float uConeLift;     // extra offset along the normal per unit of cone diameter
uniform float uMaxDistance;  // in voxels
uniform int uUseBricks;
uniform int uOnlyCone;  // diagnostic (`--only-cone`): only this cone (narrow cones: those in its region) gathers; −1: all
// Narrow cones (`--cone-rays`): uRayCount cones of half-angle atan(uRayTanHalfAngle), spread over
// the hemisphere anew at every apex, instead of the cone set; 0: the cone set.
uniform int uRayCount;
uniform float uRayTanHalfAngle;
// The narrow cones [uRayFirst, uRayEnd) of the uRayCount: a dispatch traces a few of them
// (cone_trace.cpp, kNarrowConesPerDispatch), each adding its part to what the ones before stored.
uniform int uRayFirst, uRayEnd;
// Invocations that share one apex's cones (cone_lanes.glsl): this one, lane coneLane of
// coneLanes, traces every coneLanes-th cone from its own. One lane traces them all.
int coneLane = 0, coneLanes = 1;
// The later samples of an accumulated frame (cone_trace.cpp, conesForSample): >= 0, where this
// sample's narrow cones start in a sequence of directions that each block of traced pixels
// continues over the samples; -1: every apex draws its own directions.
uniform int uRaySequence;
uniform vec3 uVoxelOrigin;
uniform float uVoxelScale;
layout(std430, binding = SSBO_CELL_OPACITY) buffer ConeCellOpacity { uint coneCellOpacity[]; };  // (αx, αy, αz, α)

// The cone being traced: its axis, and E[max(±d_a, 0)] per axis over its directions
// (cone_spread.glsl).
vec3 coneAxis;
vec3 coneAlongPlus, coneAlongMinus;

// Whether a sample in an empty node also reads ahead across the cone (sampleLevel). A narrow cone
// passing low over a floor sees it only across its axis; when the floor lies at the top of its
// node, the cone's samples just above it stand in the empty node above, and without these reads
// the cone passes over the floor and through it without meeting it (Sponza's courtyard floor is
// such a floor at 256³). A wide cone's reads across it from an empty node reach far beyond its
// footprint: the cone set keeps reading only along its axis there (reading across too was
// measured to brighten the cones that look across a floor, already too bright:
// docs/benchmark.md, "Narrow cones instead of the cone set").
bool readsAcrossEmptyNodes() { return uRayCount > 0; }
// Shares of a narrow cone's travel below this are the far tails of its spread: not read there.
const float NEGLIGIBLE_SHARE = 1e-3;

// Directions at more than about 41° from the cone's axis (cosine below this) are read one level
// finer (sampleLevel). A ring cone of the 5-cone set leans 51° from the surface normal, so the
// read along that normal falls on this side: read at the cone's own level it reached past the
// footprint into the lit floor below a gallery's vaults (docs/benchmark.md, "Reads across the cone
// from 41°"). Below about 39° a ring cone's main direction would be read finer too, and
// CameraBalcony's dim galleries then received several times the path tracer's light.
// Narrow cones barely spread: what they read "across" are the smaller components of their own
// direction, and they keep the threshold of 60° they were measured best with.
const float LATERAL_ALIGNMENT = 0.75;
const float NARROW_LATERAL_ALIGNMENT = 0.5;
float lateralAlignment() { return uRayCount > 0 ? NARROW_LATERAL_ALIGNMENT : LATERAL_ALIGNMENT; }

// How far ahead of p a read across the axis starts, in spacings of the brick it reads
// (`finerSpacings`: that of the finer level, else the coarser one's, half as many): narrow cones
// half a finer spacing, about their footprint's radius, from occupied and empty nodes alike
// (sampleLevel); the cone set, whose rules were tuned with it, a whole one.
float lateralAhead(bool finerSpacings) {
    float ahead = uRayCount > 0 ? 0.5 : 1.0;
    return finerSpacings ? ahead : 0.5 * ahead;
}

// Where p lies in the brick of node `node` (level `level`), in sample spacings (0..2 per axis).
vec3 brickPosition(uint node, int level, vec3 p) {
    float size = float(1 << (uLevels - level));
    return clamp((p - vec3(unpackCell(nodeCoord[node])) * size) / size, 0.0, 1.0) * 2.0;
}

// The node of level `level` containing q, a point ahead of p along axis a (`face`: the face of
// that side, −x +x −y +y −z +z), or NONE: empty or outside the grid. `known`, of knownLevel <
// level, holds p; q lies in it or, less than its edge away along a, in its neighbour there, where
// the descent starts.
uint nodeAhead(vec3 q, int level, uvec3 cell, uint known, int knownLevel, int face) {
    if (any(lessThan(q, vec3(0.0))) || any(greaterThanEqual(q, vec3(float(1 << uLevels))))) return NONE;
    uvec3 qCell = uvec3(floor(q));
    uint shift = uint(uLevels - knownLevel);
    uint node = all(equal(qCell >> shift, cell >> shift)) ? known : nodeNeighbour[known * 6u + uint(face)];
    for (int l = knownLevel + 1; l <= level && node != NONE; ++l) node = childOf(node, childSlot(qCell >> uint(uLevels - l)));
    return node;
}

// A cone at p reads, for each direction i (+a for i = 2a, −a for i = 2a + 1), the slab samples
// one spacing ahead of p along it. A slab along ±a starts at its sample and reaches one spacing
// ahead, so the samples interpolated start at p or beyond: a sample behind p would report what
// lies behind the cone, e.g. the lit top of a thin roof to a cone passing under it.
// slabAhead: from `inBrick`, p's position in the brick of its own node `node`, `ahead` spacings
// ahead: the node holding that point (itself, or its neighbour past the brick's face; NONE: empty
// space ahead) and the point's position in that node's brick.
uint slabAhead(uint node, vec3 inBrick, int i, float ahead, out vec3 at) {
    int a = i >> 1;
    bool along = (i & 1) == 0;
    at = inBrick;
    at[a] += along ? ahead : -ahead;
    if (at[a] <= 2.0 && at[a] >= 0.0) return node;
    at[a] += along ? -2.0 : 2.0;
    return nodeNeighbour[node * 6u + uint(2 * a + (along ? 1 : 0))];  // −x +x −y +y −z +z
}

// The same where p's node is empty, `ahead` spacings of level `level` ahead of p: that point may
// still lie in a node that holds geometry. A cone about to reach a wall reads the wall's slab
// before it enters the wall's node, as it would from a node of its own. Without that read a
// cone's view of a wall would depend on where its samples fall relative to the node grid, and the
// grid would print into the image as blocks of constant light. With `faceRead` (narrow cones),
// where the point ahead is empty too but less than a spacing before the face of a node that is
// not, the read is that node's face sample by one minus the distance (`share`): what
// interpolating across the face would give it, had the empty node a brick. A narrow cone's reads
// along a direction cover, sample after sample, the stretch it travels that way only if the
// reads on both sides of a face see what lies past it: without this read a sheet in the first
// slab past an empty node was counted by a quarter to three quarters, by the phase of the steps,
// and a floor under a sheet saw the emitter above the sheet through it; across the axis, a floor
// below a cone that descends over it was counted only where a read happened to fall past its
// node's face, and the light of a floor seen at a grazing angle was lost.
uint slabAheadOfEmpty(int level, vec3 p, uvec3 cell, uint known, int knownLevel, int i, bool faceRead, float ahead,
                      out vec3 at, out float share) {
    int a = i >> 1;
    bool along = (i & 1) == 0;
    const float size = float(1 << (uLevels - level));
    share = 1.0;
    vec3 q = p;
    q[a] += (along ? 0.5 : -0.5) * ahead * size;
    const int face = 2 * a + (along ? 1 : 0);
    uint holder = nodeAhead(q, level, cell, known, knownLevel, face);
    if (holder == NONE && faceRead) {
        const float faceAt = (floor(q[a] / size) + (along ? 1.0 : 0.0)) * size;
        const float before = abs(faceAt - q[a]) / (0.5 * size);  // in spacings
        vec3 beyond = q;
        beyond[a] = faceAt + (along ? 0.25 : -0.25) * size;
        if (before < 1.0) holder = nodeAhead(beyond, level, cell, known, knownLevel, face);
        if (holder != NONE) {
            share = 1.0 - before;
            at = brickPosition(holder, level, beyond);
            at[a] = along ? 0.0 : 2.0;  // its face sample
            return holder;
        }
    }
    at = holder != NONE ? brickPosition(holder, level, q) : vec3(0.0);
    return holder;
}

// What the cone sees at p at level `level` through p's node `node` there (NONE: empty; `known`
// of knownLevel is then a node holding p, for nodeAhead): (L·τ, τ) summed over the six directions,
// each the cone's share along it × the slab ahead of p along it.
// A slab read ahead reaches up to two of its level's spacings from p, about the footprint's
// diameter: along the axis that is where the cone goes next, but sideways it lies outside the
// cone (a horizontal cone high in a gallery would see the sunlit courtyard floor below it).
// Directions more than 41° from the axis are therefore read one level finer, for narrow cones
// half that level's spacing ahead of p: the slab then covers, on average, the stretch from p to
// one finer spacing ahead, about the footprint's radius on that side (lateralAhead). They are
// read from `finer`, the node one level finer at p; where it is empty, from `node`'s coarser
// slabs starting where the finer read would; where `node` is empty too (narrow cones), from the
// finer node ahead, with its face read (slabAheadOfEmpty). A whole coarse spacing ahead would
// reach one to two footprints away: a cone passing over a sunlit floor would collect its light
// while still far above it, and a cone passing beside a column would be blocked by it.
// With bricks, trilinear inside the bricks; without (`--no-bricks`), the nearest sample: the
// unfiltered data, for comparison.
vec4 sampleLevel(uint node, int level, uint finer, vec3 p, uvec3 cell, uint known, int knownLevel) {
    vec3 inNode = node != NONE ? brickPosition(node, level, p) : vec3(0.0);
    vec3 inFiner = finer != NONE ? brickPosition(finer, level + 1, p) : inNode;
    vec3 poolSize = vec3(textureSize(uDirectional, 0));
    vec4 value = vec4(0.0);
    // Every direction in turn, with one lookup site (llvmpipe: a second site of the same texture
    // in another branch read zeros).
    for (int i = 0; i < 6; ++i) {
        int a = i >> 1;
        bool along = (i & 1) == 0;
        bool lateral = (along ? coneAxis[a] : -coneAxis[a]) < lateralAlignment();
        vec3 at;
        float share = 1.0;
        uint holder = NONE;
        float weight = along ? coneAlongPlus[a] : coneAlongMinus[a];
        // A narrow cone travels along one side of each axis only: the other side's share is
        // exactly 0, and its lookups would add nothing.
        if (weight == 0.0) continue;
        if (node == NONE) {
            if (!lateral)
                holder = slabAheadOfEmpty(level, p, cell, known, knownLevel, i, readsAcrossEmptyNodes(), 1.0, at, share);
            else if (readsAcrossEmptyNodes() && weight > NEGLIGIBLE_SHARE)
                holder = slabAheadOfEmpty(level + 1, p, cell, known, knownLevel, i, true, lateralAhead(true), at, share);
        } else {
            bool fromFiner = lateral && finer != NONE;
            float ahead = lateral ? lateralAhead(fromFiner || level + 1 == uLevels) : 1.0;
            holder = slabAhead(fromFiner ? finer : node, fromFiner ? inFiner : inNode, i, ahead, at);
        }
        if (holder == NONE) continue;  // empty space ahead
        vec3 sampleAt = uUseBricks != 0 ? at : round(at);
        value += weight * share * texture(uDirectional, (vec3(directionalBrickOrigin(holder, i)) + 0.5 + sampleAt) / poolSize);
    }
    return value;
}

// The cone's diameter at distance t, in voxels (never below one voxel, the finest sample).
float coneDiameter(float t, float tanHalfAngle) { return max(2.0 * t * tanHalfAngle, 1.0); }

// The footprint a cone samples at distance t, as a level of detail (2^lod voxels): its diameter,
// but never coarser than half its height above the surface it starts from. A sample's slabs
// reach up to two of its level's spacings from p (interpolation and slab): sampled coarser, a cone
// near its surface would read the surface itself, or what lies behind it (the lit side of a thin
// wall, a roof's sunlit top), and be blocked or lit by it. Near the surface cones are therefore
// sampled finer than their width; at a distance their width decides. `startHeight`: how far the
// cone's origin lies off that surface, in voxels.
float coneLod(float t, float tanHalfAngle, vec3 direction, vec3 normal, float startHeight) {
    float diameter = coneDiameter(t, tanHalfAngle);
    float height = startHeight + t * dot(direction, normal);
    return min(log2(diameter), log2(max(height, 1.0)) - 1.0);
}

// The length of the march's step for a cone of `diameter` sampled at `lod` (coneLod): uConeStep ×
// the diameter, but for a narrow cone never longer than the spacing of the one level its sample
// reads (the voxels: one voxel). Its reads cover one spacing ahead along each direction; a longer
// step leaves gaps between them in which a thin sheet goes unseen. (The cone set blends two
// levels, the finer at least half its diameter: its default step of half a diameter leaves none.)
float stepLength(float diameter, float lod) {
    float step = uConeStep * diameter;
    if (uRayCount == 0) return step;
    lod = clamp(lod, 0.0, float(uLevels - 1));
    float spacing = exp2(floor(lod) + (fract(lod) >= 0.5 ? 1.0 : 0.0));  // the level sampleRadiance reads
    return min(step, spacing);
}

// The coarser of the two levels sampled for a footprint of 2^lod voxels.
int coarseLevelFor(float lod) {
    return max(uLevels - 1 - int(floor(clamp(lod, 0.0, float(uLevels - 1)))) - 1, 0);
}

// Whether every read of a sample at p whose coarser level is coarseLevel stays inside the empty
// node [lo, lo + size]³: then it sees nothing and can be skipped. The reads ahead go half that
// level's node edge along the axes within 41° of the cone's axis (sampleLevel), and with
// readsAcrossEmptyNodes along every direction the cone travels at all.
bool readsStayInside(vec3 p, int coarseLevel, vec3 lo, float size) {
    // Narrow cones also read a face sample up to a spacing past the point ahead (slabAheadOfEmpty).
    float reach = (readsAcrossEmptyNodes() ? 1.0 : 0.5) * float(1 << (uLevels - coarseLevel));
    bool inside = true;
    for (int a = 0; a < 3; ++a) {
        if (readsAcrossEmptyNodes()) {
            if (coneAlongPlus[a] > NEGLIGIBLE_SHARE && p[a] + reach >= lo[a] + size) inside = false;
            if (coneAlongMinus[a] > NEGLIGIBLE_SHARE && p[a] - reach < lo[a]) inside = false;
            continue;
        }
        float ahead = p[a] + (coneAxis[a] > 0.0 ? reach : -reach);
        if (abs(coneAxis[a]) >= lateralAlignment() && (ahead < lo[a] || ahead >= lo[a] + size)) inside = false;
    }
    return inside;
}

// What a narrow cone thinner than a voxel sees at p: the voxels themselves. Each direction i (±a)
// reads the voxel window one voxel long ahead of p along it, [p, p ± 1] along a, as a leaf slab
// does, but only the column p lies in: the voxel holding p and the next along ±a, each weighted by
// its share of the window, with its opacity along a and the share of its light that leaves
// towards the cone (facing.glsl), (L·f·τ, τ) with τ = −ln(1 − α_a). The leaf bricks a wider cone
// reads average 2×2 voxels across each slab and are interpolated between voxel corners: a ray
// through them sees a gap of two voxels half closed and a sunlit strip two voxels wide spread
// over four, where the voxels hold both sharp.
vec4 voxelSeen(uint voxel, int i, float share) {
    if (voxel == NONE || share <= 0.0) return vec4(0.0);
    uint index = voxel - uLevelStart[uLevels];
    return share * voxelSeenAlong(index, i, unpackUnorm4x8(coneCellOpacity[index])[i >> 1]);
}

// `known` is p's deepest node, of level `knownLevel`: its leaf node, or, where that is empty, the
// node above it that holds p (p's own voxel is then empty, and the next one is found from it).
// Reading the leaf bricks ahead of an empty leaf node instead read from half a node ahead of p,
// a voxel past the window of the sample after it: a cone crossing a sheet inside its voxels
// counted only part of the sheet's voxel and saw the light beyond it.
// Until a cone has left the layer of voxels it starts in along an axis, it sees the light of its
// own voxel along that axis only where the voxel's lit surface lies ahead of it (facing.glsl,
// litPlace; its opacity always). A voxel does not otherwise know where in it its surface lies, and
// a cone that starts in the layer of another surface cannot tell on which side of it it is: cones
// from the top of a wall just under a ceiling whose top is sunlit travel inside the ceiling's
// voxels, below the ceiling, and read the light of its top, which leaves upwards, as if the
// ceiling lay below them (a closed room beside a sunlit one lit up at single pixels). A cone that
// crossed into a layer from outside has the surfaces there ahead of it. Where the place is not known (emission, pooled slivers) the light is seen.
uvec3 coneStartCell = uvec3(0u);  // the cell a cone starts in (traceCone)

bool litBehind(uint voxel, int a, float at, bool along) {
    vec3 place;
    if (!litPlace(voxel - uLevelStart[uLevels], place)) return false;
    return along ? place[a] < at : place[a] > at;
}

vec4 sampleVoxels(vec3 p, uint known, int knownLevel) {
    uvec3 cell = uvec3(clamp(floor(p), vec3(0.0), vec3(float((1 << uLevels) - 1))));
    uint own = knownLevel == uLevels - 1 ? childOf(known, childSlot(cell)) : NONE;
    vec3 inCell = p - vec3(cell);
    vec4 value = vec4(0.0);
    for (int i = 0; i < 6; ++i) {
        int a = i >> 1;
        bool along = (i & 1) == 0;
        float weight = along ? coneAlongPlus[a] : coneAlongMinus[a];
        if (weight <= NEGLIGIBLE_SHARE) continue;
        float ownShare = along ? 1.0 - inCell[a] : inCell[a];  // of the window, inside p's voxel
        vec3 q = vec3(cell) + 0.5;
        q[a] += along ? 1.0 : -1.0;
        uint next = nodeAhead(q, uLevels, cell, known, knownLevel, 2 * a + (along ? 1 : 0));
        vec4 ownSeen = voxelSeen(own, i, ownShare);
        if (own != NONE && cell[a] == coneStartCell[a] && litBehind(own, a, inCell[a], along)) ownSeen.rgb = vec3(0.0);
        value += weight * (ownSeen + voxelSeen(next, i, 1.0 - ownShare));
    }
    return value;
}

// The node a cone's last sample descended through one level above its coarser sampled level
// (descentLevel: its level, descentCoord: its coordinate there). Consecutive samples of a cone lie
// half a footprint apart, so the next one usually lies in the same node, and its descent resumes
// there instead of at the root: the same nodes are found, with fewer lookups.
uint descentNode = 0u;
int descentLevel = 0;
uvec3 descentCoord = uvec3(0u);

// Radiance at p (voxel space) for a footprint of 2^lod voxels: the two nearest levels
// (sampleLevel), linear between them (narrow cones: the nearer one). Returns false when p lies in an empty node of the coarser
// level whose reads stay inside it, with the node (emptyLo, emptyLevel) and tSkip where the ray
// leaves it.
bool sampleRadiance(vec3 p, float lod, vec3 origin, vec3 invDirection, out vec4 value, out float tSkip,
                    out vec3 emptyLo, out int emptyLevel) {
    lod = clamp(lod, 0.0, float(uLevels - 1));
    int fineLevel = uLevels - 1 - int(floor(lod));
    int coarseLevel = max(fineLevel - 1, 0);
    float blend = fract(lod);
    uvec3 cell = uvec3(clamp(floor(p), vec3(0.0), vec3(float((1 << uLevels) - 1))));
    uint node = 0u, coarseNode = coarseLevel == 0 ? 0u : NONE, fineNode = NONE;
    int level = 0;
    uint finerNode = NONE;  // one level below the fine one, for the directions across the cone
    if (descentLevel > 0 && descentLevel <= coarseLevel && all(equal(cell >> uint(uLevels - descentLevel), descentCoord))) {
        node = descentNode;
        level = descentLevel;
        if (level == coarseLevel) coarseNode = node;
    }
    const int nextDescentLevel = max(coarseLevel - 1, 0);
    uint nextDescentNode = nextDescentLevel == 0 ? 0u : (level == nextDescentLevel ? node : NONE);
    for (level = level + 1; level <= fineLevel; ++level) {
        uint child = childOf(node, childSlot(cell >> uint(uLevels - level)));
        if (child == NONE) break;
        node = child;
        if (level == coarseLevel) coarseNode = node;
        if (level == nextDescentLevel) nextDescentNode = node;
    }
    if (nextDescentNode != NONE && nextDescentLevel <= level) {
        descentNode = nextDescentNode;
        descentLevel = nextDescentLevel;
        descentCoord = cell >> uint(uLevels - nextDescentLevel);
    }
    if (level > fineLevel) {
        fineNode = node;
        if (fineLevel + 1 < uLevels) finerNode = childOf(node, childSlot(cell >> uint(uLevels - fineLevel - 1)));
    }
    if (coarseNode == NONE) {  // empty at the coarse level (or above)
        emptyLevel = level;
        float size = float(1 << (uLevels - level));
        emptyLo = vec3(cell >> uint(uLevels - level)) * size;
        tSkip = rayBox(origin, invDirection, emptyLo, emptyLo + size).y;
        if (readsStayInside(p, coarseLevel, emptyLo, size)) {
            value = vec4(0.0);
            return false;
        }
    }
    // Where a node is missing, `node` is p's deepest one, of level − 1: the reads ahead of p
    // look up their nodes from it (nodeAhead).
    uint nodes[2] = uint[2](fineNode, coarseNode);
    uint finerNodes[2] = uint[2](finerNode, fineLevel == coarseLevel ? finerNode : fineNode);
    int levels[2] = int[2](fineLevel, coarseLevel);
    // A narrow cone reads only the level nearer its footprint: the blend of two levels hides the
    // seams where a wide cone's samples change level, which narrow cones, whose directions change
    // from pixel to pixel, average out anyway; one level halves their lookups.
    if (uRayCount > 0) {
        const int k = fineLevel == coarseLevel || blend >= 0.5 ? 1 : 0;
        if (k == 0 && fineLevel == uLevels - 1) {
            value = sampleVoxels(p, node, level - 1);  // p's leaf node, or its deepest one where that is empty
            return true;
        }
        value = sampleLevel(nodes[k], levels[k], finerNodes[k], p, cell, node, level - 1);
        return true;
    }
    vec4 samples[2];
    for (int k = 0; k < 2; ++k) samples[k] = sampleLevel(nodes[k], levels[k], finerNodes[k], p, cell, node, level - 1);
    value = fineLevel == coarseLevel ? samples[1] : mix(samples[0], samples[1], blend);
    return true;
}

// One cone: accumulated premultiplied radiance (rgb) and opacity (a). Samples may be lifted off
// the surface along its normal by uConeLift × the cone diameter (0 by default: coneLod keeps
// samples off their own surface).
vec4 traceCone(vec3 origin, vec3 normal, vec3 direction, float tanHalfAngle, float startHeight) {
    vec3 invDirection = 1.0 / direction;
    float n = float(1 << uLevels);
    float tEnd = min(rayBox(origin, invDirection, vec3(0.0), vec3(n)).y, uMaxDistance);
    vec4 accumulated = vec4(0.0);
    float t = 1.0;
    descentLevel = 0;
    coneStartCell = uvec3(clamp(floor(origin), vec3(0.0), vec3(n - 1.0)));
    for (int i = 0; i < 1024 && t < tEnd && accumulated.a < 0.99; ++i) {
        float diameter = coneDiameter(t, tanHalfAngle);
        vec3 p = origin + direction * t + normal * (uConeLift * diameter);  // from t, never accumulated
        vec4 value;
        float tSkip;
        vec3 emptyLo;
        int emptyLevel;
        float lod = coneLod(t, tanHalfAngle, direction, normal, startHeight);
        if (!sampleRadiance(p, lod, origin, invDirection, value, tSkip, emptyLo, emptyLevel)) {
            // Skip the empty node along the very sample sequence a plain march would take
            // (arithmetic only, no lookups): jumping straight to the node's exit would shift the
            // step phase from pixel to pixel and print the node grid into the image as moiré.
            // Stop where the widening cone starts sampling a level above the empty node, or where
            // a sample's reads reach out of it.
            float size = float(1 << (uLevels - emptyLevel));
            bool skip = true;
            while (skip) {
                t += stepLength(coneDiameter(t, tanHalfAngle), lod);
                lod = coneLod(t, tanHalfAngle, direction, normal, startHeight);
                int coarseLevel = coarseLevelFor(lod);
                vec3 next = origin + direction * t + normal * (uConeLift * coneDiameter(t, tanHalfAngle));
                skip = t < tSkip && coarseLevel >= emptyLevel && readsStayInside(next, coarseLevel, emptyLo, size);
                ++samplesSaved;
            }
            --samplesSaved;  // the sample that found the node empty was looked up
            continue;
        }
        ++samplesTaken;
        // value = (L·τ, τ): τ is the optical depth per voxel length, so the step of
        // uConeStep × diameter voxels has opacity 1 − exp(−τ·step); its radiance is L = rgb/τ.
        // The directions' sum is negative where the sample sees the dark side of a surface lit at
        // an angle to the axes (radiance_normalize.comp, darkSideSigned): it sends nothing.
        float step = stepLength(diameter, lod);
        float alpha = opacityOver(value.a, step);
        vec3 radiance = value.a > 1e-6 ? max(value.rgb * (alpha / value.a), vec3(0.0)) : vec3(0.0);
        accumulated.rgb += (1.0 - accumulated.a) * radiance;
        accumulated.a += (1.0 - accumulated.a) * alpha;
        t += step;
    }
    return accumulated;
}


// The share of a cone (axis `direction`, half-angle atan(tanHalfAngle)) in front of the plane
// of unit normal `n`: from its axis' elevation above the plane, linear across the cone's width.
float coneShareAbove(vec3 direction, float tanHalfAngle, vec3 n) {
    float elevation = asin(clamp(dot(direction, n), -1.0, 1.0));
    return clamp(0.5 + 0.5 * elevation / atan(tanHalfAngle), 0.0, 1.0);
}

// Two numbers in [0, 1) from the bits of a point: the same point always gives the same pair, so
// frames stay deterministic, and neighbouring points get unrelated ones.
vec2 hashToUnitSquare(vec3 p) {
    uvec3 b = floatBitsToUint(p);
    uint h = b.x * 73856093u ^ b.y * 19349663u ^ b.z * 83492791u;
    h ^= h >> 16; h *= 0x7feb352du; h ^= h >> 15; h *= 0x846ca68bu; h ^= h >> 16;
    return vec2(float(h & 0xffffu), float(h >> 16)) / 65536.0;
}

// The shift of a traced pixel's narrow-cone directions (narrowConePoint), from its block of traced
// pixels `block`. The upsampling and the edge-aware filter average the cones of neighbouring
// blocks, so the first sample stratifies their shifts: within a tile of 8×8 blocks the shift is
// the rank-2 lattice x·α + y·α² (α: the R2 sequence's step), so that the blocks of any window, a
// row, a column, a square, take shifts spread evenly over the square; its first coordinate spans
// one of the N cones' strata of sin²θ (1/N), whose gaps it fills (over the whole square, α's 0.755
// is nearly 3/4: with 4 cones a row of blocks would repeat their elevations). Together they cover
// the directions far more evenly than independent shifts, which leaves less noise after the
// filter. A hash of the tile moves them all, so tiles do not repeat one pattern. The later
// samples of an accumulated frame continue one sequence per block instead (narrowConePoint),
// shifted by a hash of the block. From the block, not from the cone's apex: its bits change with
// the scene's scale and place (the same view of a scene moved far away would get other
// directions, other noise), the block's do not.
vec2 narrowConeShift(ivec2 block) {
    if (uRaySequence >= 0) return hashToUnitSquare(vec3(vec2(block), -1.0));
    const vec2 inTile = vec2(block & 7);
    vec2 lattice = fract(inTile.x * R2_STEP + inTile.y * fract(R2_STEP * R2_STEP));
    lattice.x /= float(uRayCount);
    return fract(lattice + hashToUnitSquare(vec3(vec2(block >> 3), -2.0)));
}

#ifdef STORE_CONE_SAMPLES
// Each narrow cone's own result (cone_trace.comp, for cone_reuse.comp): for cell coneSampleCell of
// the traced image, cone k's (premultiplied radiance, opacity) and (axis, 1 if traced, 0 if it
// lay behind the triangle's plane); -1: the apex is not a traced cell's.
layout(std430, binding = SSBO_CONE_SAMPLES) writeonly buffer ConeSamples { vec4 coneSamples[]; };
ivec2 coneSampleCell = ivec2(-1);
uniform int uConeSampleRowLength;  // cells per row of the traced image
uniform int uStoreConeSamples;     // 0: cone_reuse does not run, nothing is stored

void storeConeSample(int k, vec3 direction, vec4 cone, bool traced) {
    if (coneSampleCell.x < 0 || uStoreConeSamples == 0) return;
    const int at = 2 * ((coneSampleCell.y * uConeSampleRowLength + coneSampleCell.x) * uRayCount + k);
    coneSamples[at] = cone;
    coneSamples[at + 1] = vec4(direction, traced ? 1.0 : 0.0);
}
#endif

// Whether the axis of a pixel's narrow cone meets a surface nearer than where the cone starts, and
// what that surface sends back (near_field.glsl: the camera's cones, against the G-buffer); the
// voxels' gathers have no G-buffer and meet nothing.
#ifdef SCREEN_NEAR_FIELD
bool nearFieldHit(vec3 direction, out vec4 seen);  // near_field.glsl

// The near field's surface met from the side the camera does not see (near_field.glsl): what the
// first lit voxel along the axis from `point` (on a surface of unit `normal`), within `length`
// scene units and one voxel more (a surface on a voxel's face lies in the voxel past it as much as
// in the one before), sends back along it: its radiance times its exit shares towards the pixel,
// as a cone passing through it would see it. The G-buffer holds only the side the camera sees; the
// voxels hold the light of both. Voxels whose lit surface (its photons' mean place) lies less than
// kOffOwnSurface off the pixel's plane are passed: a ray at a grazing angle crosses the voxels of
// its own floor first, whose light leaves along the floor's normal, not towards the pixel.
const float kOffOwnSurface = 0.25;  // voxels
bool hiddenSideLight(vec3 point, vec3 normal, vec3 direction, float length, out vec3 radiance) {
    radiance = vec3(0.0);
    const vec3 start = (point - uVoxelOrigin) * uVoxelScale;
    const uvec3 own = uvec3(floor(start));
    const float span = length * uVoxelScale + 1.0;
    const int steps = max(int(ceil(2.0 * span)), 1);  // two a voxel: no voxel along the axis skipped
    for (int k = 1; k <= steps; ++k) {
        const vec3 p = start + direction * (span * float(k) / float(steps));
        if (any(lessThan(p, vec3(0.0))) || any(greaterThanEqual(p, vec3(float(1 << uLevels))))) return false;
        const uvec3 cell = uvec3(floor(p));
        if (all(equal(cell, own))) continue;
        const uint voxel = findNode(cell, uLevels);
        if (voxel == NONE) continue;
        const uint index = voxel - uLevelStart[uLevels];
        vec3 place;
        if (!litPlace(index, place) || dot(vec3(cell) + place - start, normal) < kOffOwnSurface) continue;
        const vec4 opacity = unpackUnorm4x8(coneCellOpacity[index]);
        vec4 seen = vec4(0.0);
        for (int a = 0; a < 3; ++a) seen += abs(direction[a]) * voxelSeenAlong(index, 2 * a + (direction[a] < 0.0 ? 1 : 0), opacity[a]);
        radiance = seen.a > 0.0 ? max(seen.rgb / seen.a, vec3(0.0)) : vec3(0.0);
        return true;
    }
    return false;
}
#else
bool nearFieldHit(vec3 direction, out vec4 seen) {
    seen = vec4(0.0);
    return false;
}
#endif

// How far off its surface a narrow cone whose axis makes `cosine` with the normal starts, in voxels:
// uConeOffset, but lower for an axis within about 19° of the surface, down to two thirds of it. The
// near field follows the axis up to uConeOffset high, or three times uConeOffset along it at a
// grazing angle (near_field.glsl); the cone then starts straight above the pixel, so what stands
// lower than its start beyond the near field's reach (a kerb, the foot of a wall a metre away, a
// fin two voxels tall) lies under every grazing cone. Starting lower, they see it; starting a
// voxel or less off the surface, they read the surface's own voxels and see through a wall at
// 45° to the grid (docs/benchmark.md, "Grazing cones start lower").
const float kLowestGrazingStart = 2.0 / 3.0;  // of uConeOffset
float grazingConeStart(float cosine) {
    return uConeOffset * clamp(3.0 * cosine, kLowestGrazingStart, 1.0);
}

// Narrow cones instead of the cone set (`--cone-rays`, and the later samples of an accumulated
// frame): uRayCount cones, each of weight π/N, whose axes sample the cosine-weighted hemisphere
// (sin²θ and azimuth uniform, narrow_cone_directions.glsl) shifted by `shift` (narrowConeShift).
// A cone a few voxels wide keeps its samples on fine levels, where a sample's opacity and light
// are the geometry's own, so occlusion and light arrive from where the path tracer finds them; the
// noise of N directions per pixel is what the upsampling, the edge-aware filter and the samples'
// average remove. The share of a cone behind the triangle's plane is blocked by it, as in the
// cone set; a cone whose axis meets a surface before it starts takes that surface's light.
vec4 gatherNarrowCones(vec3 origin, vec3 normal, vec3 surfaceNormal, vec2 shift) {
    vec3 tangent, bitangent;
    orthonormalBasis(normal, tangent, bitangent);
    const float count = float(uRayCount);
    // precise: each cone's product is rounded before it is added, as when the work group adds
    // the cones of its lanes (cone_lanes.glsl); a GPU's compiler would otherwise fuse the two
    // here, not there, and one lane and four would differ in their last bits.
    precise vec4 gathered = vec4(0.0);
    for (int k = uRayFirst + coneLane; k < uRayEnd; k += coneLanes) {
        vec3 d = cosineWeightedDirection(narrowConePoint(k, count, shift, uRaySequence));
        if (uOnlyCone >= 0 && coneRegionOf(uConeCount, d) != uOnlyCone) continue;
        vec3 direction = normalize(d.x * tangent + d.y * bitangent + d.z * normal);
        vec4 cone = vec4(0.0, 0.0, 0.0, 1.0);
        if (dot(direction, surfaceNormal) > 0.0 && !nearFieldHit(direction, cone)) {
            coneAxis = direction;
            coneSpread(direction, uRayTanHalfAngle, coneAlongPlus, coneAlongMinus);
            const float startHeight = grazingConeStart(dot(direction, normal));
            cone = traceCone(origin - normal * (uConeOffset - startHeight), normal, direction, uRayTanHalfAngle, startHeight);
        }
#ifdef STORE_CONE_SAMPLES
        storeConeSample(k, direction, cone, dot(direction, surfaceNormal) > 0.0);
#endif
        gathered += (PI / count) * cone;
    }
    return gathered;
}

// The cone set around `normal` from `origin` (voxel space): irradiance E (rgb) and the occlusion
// Σ weight·opacity (a; π when every cone is blocked). `surfaceNormal` is the surface's own side
// (a triangle's geometric normal; `normal` itself where there is none): light cannot arrive from
// behind it, so where smooth shading leans `normal` away from it, each cone counts only the share
// it has in front of that plane beyond the share it has in front of its own (which the cone set's
// weights already account for: on a flat surface every cone keeps its whole weight).
// `narrowShift` shifts the directions of narrow cones (narrowConeShift).
vec4 gatherIrradiance(vec3 origin, vec3 normal, vec3 surfaceNormal, vec2 narrowShift) {
    if (uRayCount > 0) return gatherNarrowCones(origin, normal, surfaceNormal, narrowShift);
    vec3 tangent, bitangent;
    orthonormalBasis(normal, tangent, bitangent);
    precise vec4 gathered = vec4(0.0);  // as in gatherNarrowCones
    for (int c = coneLane; c < uConeCount; c += coneLanes) {
        if (uOnlyCone >= 0 && c != uOnlyCone) continue;
        vec3 d = uConeDirection[c];
        vec3 direction = normalize(d.x * tangent + d.y * bitangent + d.z * normal);
        float tanHalfAngle = uConeTanHalfAngle[c];
        float inFront = min(coneShareAbove(direction, tanHalfAngle, surfaceNormal) /
                                max(coneShareAbove(direction, tanHalfAngle, normal), 1e-3), 1.0);
        vec4 cone = vec4(0.0, 0.0, 0.0, 1.0);  // the share behind the triangle: blocked by it
        if (inFront > 0.0) {
            coneAxis = direction;
            coneSpread(direction, tanHalfAngle, coneAlongPlus, coneAlongMinus);
            cone = mix(cone, traceCone(origin, normal, direction, tanHalfAngle, uConeOffset), inFront);
        }
        gathered += uConeWeight[c] * cone;
    }
    return gathered;
}
