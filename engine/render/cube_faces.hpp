#pragma once
// The six faces of the cube of views around a point light. A point light's light-view maps are
// these faces, each a square perspective view along its axis; shaders/lights.glsl gives each face
// exactly the directions whose largest component lies along its axis (cubeFace there), so the
// faces share the light between them with no overlap.
#include <glm/glm.hpp>

namespace vct {

constexpr int kCubeFaces = 6;

// Face 0/1 = +x/−x, 2/3 = +y/−y, 4/5 = +z/−z: the numbering of cubeFace() in lights.glsl.
inline glm::dvec3 cubeFaceAxis(int face) {
    glm::dvec3 axis(0.0);
    axis[face / 2] = face % 2 == 0 ? 1.0 : -1.0;
    return axis;
}

// Each face's map reaches this many texels beyond the face's own square on every side, so that a
// shadow lookup next to a seam (pushed off the surface, filtered over neighbouring texels) still
// finds depths inside its own map instead of the border, which counts as lit.
constexpr int kCubeFaceMarginTexels = 4;

}  // namespace vct
