// The regions of the hemisphere that the cones of a set cover (render/cone_set.cpp): the cap,
// then rings of equal sectors centred on their cones' axes. The C++ twin, coneRegionOf in
// render/cone_set.cpp, is what the path tracer's --cone-region uses; tests/cone_set_test.cpp
// checks that the two agree. Requires math.glsl.

// Which cone of a set of `count` cones (1, 5, 6, 9 or 16) owns the region that the tangent-space
// direction `local` (z along the normal) lies in. Lets `--only-cone K` pick the narrow cones of
// cone K's region.
int coneRegionOf(int count, vec3 local) {
    float z = local.z / length(local);
    float sin2 = max(1.0 - z * z, 0.0);
    float share = 1.0 / float(count);
    float outer = share;  // the cap
    if (sin2 <= outer || count == 1) return 0;
    int rings[2] = int[2](count == 16 ? 5 : count - 1, count == 16 ? 10 : 0);
    int first = 1;
    for (int ring = 0; ring < 2 && rings[ring] > 0; ++ring) {
        int m = rings[ring];
        outer += float(m) * share;
        bool last = ring == 1 || rings[1] == 0;
        if (sin2 <= outer || last) {
            float sector = atan(local.y, local.x) * float(m) / (2.0 * PI) - 0.5 * float(ring);
            // The nearest axis, wrapped into 0..m−1 (GLSL's % is undefined for negative numbers).
            return first + int(mod(floor(sector + 0.5), float(m)));
        }
        first += m;
    }
    return 0;
}
