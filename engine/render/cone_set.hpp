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

}  // namespace vct
