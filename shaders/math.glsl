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
