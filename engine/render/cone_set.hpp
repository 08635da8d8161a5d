#pragma once
// Diffuse cone sets (DESIGN 5.5). The hemisphere around the normal is partitioned into regions
// of equal cosine-weighted solid angle, one per cone: a cap around the normal and rings split
// into equal azimuthal sectors. A cone's weight is its region's ∫cosθ dω, so the weights sum to
// exactly π and a constant-radiance environment L gives irradiance π·L whatever the set. Its axis
// is the region's median in sin²θ (the cosine-weighted median), its half-angle that of a cone
// with the region's solid angle.
//
//   --cones 1:  the whole hemisphere as one cone (axis = normal)
//   --cones 5:  cap + ring of 4          --cones 6:  cap + ring of 5
//   --cones 9:  cap + ring of 8          --cones 16: cap + ring of 5 + ring of 10
// With N cones each region has weight π/N; ring k spans sin²θ ∈ [s_{k−1}, s_k] with
// s_k − s_{k−1} = (cones in ring k)/N and the cap sin²θ ∈ [0, 1/N].
#include <vector>

#include <glm/glm.hpp>

namespace vct {

struct Cone {
    glm::vec3 direction;  // tangent space: z = surface normal
    float halfAngle;      // radians
    float weight;         // ∫cosθ dω of the cone's region (sr)
};

std::vector<Cone> makeConeSet(int count);  // throws for counts other than 1, 5, 6, 9, 16
const char* coneSetNames();                // "1|5|6|9|16"

// The index (in makeConeSet(count)'s order) of the region that holds the direction `local`
// (tangent space, z ≥ 0): the cap or, in its ring, the sector of the nearest cone axis. The
// light arriving in a cone's region is what that cone alone should gather (`vct reference
// --cone-region`, `vct render --only-cone`: which cones are right, and where).
int coneRegionOf(int count, glm::vec3 local);

// The tangent frame the cones are laid out in around the unit normal n (Duff et al. 2017): the
// same formula as orthonormalBasis in shaders/math.glsl, which the GPU passes use.
void coneTangentFrame(glm::vec3 n, glm::vec3& tangent, glm::vec3& bitangent);

}  // namespace vct
