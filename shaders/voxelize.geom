#version 450
// Voxelization, geometry stage: each triangle is projected orthographically along its dominant
// axis (the one where it has the largest area) onto an N×N viewport, one pixel per voxel column.
// The projected triangle is enlarged so that every pixel whose square it touches is rasterized
// (conservative); the fragment stage then clips the triangle to each pixel exactly. Thin or
// needle-like triangles, whose enlarged corners would shoot far away, are drawn as their enlarged
// bounding rectangle instead: correctness never depends on the enlargement, only cost does.
layout(triangles) in;
layout(triangle_strip, max_vertices = 4) out;

in vec3 vVoxel[];
in vec2 vUv[];
in vec3 vColor[];

uniform float uViewportSize;  // N, as a float

// Whole triangle, constant over the primitive: the fragment stage clips it per pixel.
flat out vec3 gTri0;      // projected vertices: xy on the viewport, z = depth (voxels)
flat out vec3 gTri1;
flat out vec3 gTri2;
flat out int gAxis;       // 0: projected along x, 1: y, 2: z
flat out float gAreaScale;  // true area / projected area = |n| / |n[axis]|
flat out vec2 gUv0;
flat out vec2 gUv1;
flat out vec2 gUv2;
flat out vec3 gColor0;   // vertex colours
flat out vec3 gColor1;
flat out vec3 gColor2;
flat out vec3 gFaceNormal;  // the triangle's own normal: what its area projects along each axis by

// The projection frame: (u, v) on the viewport and w along the projection axis.
vec3 project(vec3 p, int axis) {
    if (axis == 0) return p.yzx;
    if (axis == 1) return p.zxy;
    return p.xyz;
}

vec3 tri[3];
vec3 triNormal;
int triAxis;
float triAreaScale;

// Outputs are undefined after EmitVertex, so every vertex carries the whole triangle again.
void emit(vec2 uv) {
    gTri0 = tri[0];
    gTri1 = tri[1];
    gTri2 = tri[2];
    gAxis = triAxis;
    gAreaScale = triAreaScale;
    gUv0 = vUv[0];
    gUv1 = vUv[1];
    gUv2 = vUv[2];
    gColor0 = vColor[0];
    gColor1 = vColor[1];
    gColor2 = vColor[2];
    gFaceNormal = triNormal;
    gl_Position = vec4(uv / uViewportSize * 2.0 - 1.0, 0.0, 1.0);
    EmitVertex();
}

void main() {
    for (int i = 0; i < 3; ++i)
        if (any(isnan(vVoxel[i])) || any(isinf(vVoxel[i]))) return;  // the loader refuses these
    vec3 n = cross(vVoxel[1] - vVoxel[0], vVoxel[2] - vVoxel[0]);
    vec3 an = abs(n);
    int axis = (an.x >= an.y && an.x >= an.z) ? 0 : (an.y >= an.z ? 1 : 2);
    float dominant = an[axis];
    // Zero area in float voxel space: a segment or a point (a sliver thinner than float precision,
    // or a sub-voxel triangle far from the origin; exactly degenerate ones the loader leaves out).
    // It still touches cells: voxelized as that segment or point, with no area, through the
    // bounding rectangle (the fragment stage's exact clipping handles degenerate polygons).
    bool degenerate = !(dominant > 0.0);
    if (degenerate) axis = 2;

    vec3 q[3] = vec3[3](project(vVoxel[0], axis), project(vVoxel[1], axis), project(vVoxel[2], axis));
    tri = q;
    triAxis = axis;
    triAreaScale = degenerate ? 0.0 : length(n) / dominant;
    triNormal = degenerate ? vec3(0.0, 0.0, 1.0) : n / length(n);

    // Counter-clockwise order in 2D so that edge normals point outwards.
    float orientation = (q[1].x - q[0].x) * (q[2].y - q[0].y) - (q[1].y - q[0].y) * (q[2].x - q[0].x);
    if (orientation < 0.0) {
        vec3 t = q[1];
        q[1] = q[2];
        q[2] = t;
    }
    // Move each edge outwards by the pixel's half diagonal along the edge normal (plus a margin
    // larger than the rasterizer's sub-pixel snapping, 1/256 px on llvmpipe) and intersect
    // neighbouring moved edges to get the enlarged triangle. The margin only costs fragment work:
    // the fragment stage clips exactly.
    const float margin = 1.0 / 32.0;
    vec2 expanded[3];
    bool wellShaped = !degenerate;
    for (int i = 0; i < 3 && wellShaped; ++i) {
        vec2 a = q[(i + 2) % 3].xy, b = q[i].xy, c = q[(i + 1) % 3].xy;
        vec2 e0 = b - a, e1 = c - b;
        vec2 n0 = normalize(vec2(e0.y, -e0.x)), n1 = normalize(vec2(e1.y, -e1.x));
        float d0 = 0.5 * (abs(n0.x) + abs(n0.y)) + margin, d1 = 0.5 * (abs(n1.x) + abs(n1.y)) + margin;
        // Solve n0·x = n0·b + d0, n1·x = n1·b + d1.
        float det = n0.x * n1.y - n0.y * n1.x;
        if (abs(det) < 1e-3) {
            wellShaped = false;
            break;
        }
        vec2 rhs = vec2(dot(n0, b) + d0, dot(n1, b) + d1);
        expanded[i] = vec2(rhs.x * n1.y - rhs.y * n0.y, n0.x * rhs.y - n1.x * rhs.x) / det;
        if (distance(expanded[i], b) > 4.0) wellShaped = false;
    }
    if (wellShaped) {
        for (int i = 0; i < 3; ++i) emit(expanded[i]);
    } else {
        vec2 lo = min(min(q[0].xy, q[1].xy), q[2].xy) - vec2(1.0);
        vec2 hi = max(max(q[0].xy, q[1].xy), q[2].xy) + vec2(1.0);
        emit(vec2(lo.x, lo.y));
        emit(vec2(hi.x, lo.y));
        emit(vec2(lo.x, hi.y));
        emit(vec2(hi.x, hi.y));
    }
    EndPrimitive();
}
