#pragma once
// Sets the `uLight` struct of shaders/lights.glsl from a Light, in the scene-local frame.
#include "gl/gl.hpp"
#include "scene/scene.hpp"

namespace vct {
void setLightUniforms(GLuint program, const Light& light, const Scene& scene);
}
