#include "render/direct_lighting.hpp"

#include "gl/shader.hpp"
#include "render/light_uniforms.hpp"

namespace vct {

DirectLighting::DirectLighting(int width, int height)
    : width_(width),
      height_(height),
      radiance_(gl::createTexture2D(GL_RGBA32F, width, height, 1, "direct radiance")),
      program_(gl::buildProgram({{GL_COMPUTE_SHADER, "direct_lighting.comp"}})) {}

void DirectLighting::render(const GBuffer& gbuffer, const Scene& scene, const std::vector<Light>& lights,
                            const std::vector<LightViewMap>& lightViews, int pcfRadius) {
    const GLuint p = program_.id();
    glUseProgram(p);
    glBindTextureUnit(0, gbuffer.albedo());
    glBindTextureUnit(1, gbuffer.normal());
    glBindTextureUnit(2, gbuffer.position());
    glBindImageTexture(0, radiance_.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
    gl::setUniform(p, "uShadowMap", 3);
    gl::setUniform(p, "uPcfRadius", pcfRadius);
    if (lights.empty()) {
        const float zero[4] = {0, 0, 0, 0};
        glClearTexImage(radiance_.id(), 0, GL_RGBA, GL_FLOAT, zero);
    }
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const LightViewMap& map = lightViews[i];
        setLightUniforms(p, lights[i], scene);
        glBindTextureUnit(3, map.depth());
        gl::setUniform(p, "uLightViewProjection", map.transform().view.viewProjection);
        gl::setUniform(p, "uShadowTexelSize", map.transform().texelWorldSize);
        gl::setUniform(p, "uShadowPerspective", map.transform().perspective ? 1 : 0);
        gl::setUniform(p, "uAccumulate", i > 0 ? 1 : 0);
        glDispatchCompute(GLuint((width_ + 7) / 8), GLuint((height_ + 7) / 8), 1);
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    }
}

}  // namespace vct
