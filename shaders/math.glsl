// Constants and small helpers shared by the shaders (the C++ side: engine/core/math_constants.hpp).
const float PI = 3.14159265358979323846;

// Two unit vectors that complete the unit vector `n` to an orthonormal basis, continuous except
// where n.z changes sign (Duff et al. 2017, "Building an Orthonormal Basis, Revisited").
void orthonormalBasis(vec3 n, out vec3 tangent, out vec3 bitangent) {
    float s = n.z >= 0.0 ? 1.0 : -1.0;
    float a = -1.0 / (s + n.z);
    float b = n.x * n.y * a;
    tangent = vec3(1.0 + s * n.x * n.x * a, s * b, -s * n.x);
    bitangent = vec3(b, s + n.y * n.y * a, -n.y);
}

// The tangent-space direction (z along the normal) of a point of the unit square read as
// (sin²θ, azimuth / 2π): uniform points give cosine-weighted directions.
vec3 cosineWeightedDirection(vec2 point) {
    float sin2 = point.x;
    float azimuth = 2.0 * PI * point.y;
    float sinTheta = sqrt(sin2);
    return vec3(sinTheta * cos(azimuth), sinTheta * sin(azimuth), sqrt(max(1.0 - sin2, 0.0)));
}
