#include "render/light_uniforms.hpp"

#include <cmath>

#include "gl/shader.hpp"

namespace vct {

void setLightUniforms(GLuint program, const Light& light, const Scene& scene) {
    const bool directional = light.type == LightType::Directional;
    gl::setUniform(program, "uLight.type", directional ? 0 : 1);
    gl::setUniform(program, "uLight.direction", glm::vec3(glm::normalize(light.direction)));
    gl::setUniform(program, "uLight.position", glm::vec3(light.position - scene.origin));
    gl::setUniform(program, "uLight.radiometric",
                   glm::vec3(light.color * (directional ? light.irradiance : light.intensity)));
    gl::setUniform(program, "uLight.cosInner", float(std::cos(glm::radians(light.innerAngleDeg))));
    gl::setUniform(program, "uLight.cosOuter", float(std::cos(glm::radians(light.outerAngleDeg))));
}

}  // namespace vct
