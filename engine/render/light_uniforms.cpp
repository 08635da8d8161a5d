#include "render/light_uniforms.hpp"

#include <cmath>

#include "gl/shader.hpp"
#include "render/cube_faces.hpp"

namespace vct {

void setLightUniforms(GLuint program, const Light& light, const Scene& scene, int face) {
    const int type = light.type == LightType::Directional ? 0 : light.type == LightType::Spot ? 1 : 2;
    const glm::dvec3 direction = light.type == LightType::Point ? cubeFaceAxis(face) : glm::normalize(light.direction);
    gl::setUniform(program, "uLight.type", type);
    gl::setUniform(program, "uLight.direction", glm::vec3(direction));
    gl::setUniform(program, "uLight.position", glm::vec3(light.position - scene.origin));
    gl::setUniform(program, "uLight.radiometric", glm::vec3(light.color * lightQuantity(light)));
    gl::setUniform(program, "uLight.cosInner", float(std::cos(glm::radians(light.innerAngleDeg))));
    gl::setUniform(program, "uLight.cosOuter", float(std::cos(glm::radians(light.outerAngleDeg))));
    gl::setUniform(program, "uLight.face", face);
}

}  // namespace vct
