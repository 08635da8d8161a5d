#pragma once
// Sets the `uLight` struct of shaders/lights.glsl from a Light, in the scene-local frame.
#include "gl/gl.hpp"
#include "scene/scene.hpp"

namespace vct {
// `face`: the cube face (render/cube_faces.hpp) of a point light's view; 0 for the other lights.
void setLightUniforms(GLuint program, const Light& light, const Scene& scene, int face = 0);
}
