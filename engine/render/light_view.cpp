#include "render/light_view.hpp"

#include <algorithm>

#include "core/error.hpp"
#include "gl/raster_state.hpp"
#include "gl/shader.hpp"
#include "render/cube_faces.hpp"
#include "render/light_uniforms.hpp"

namespace vct {

namespace {

// Hardware-filtered shadow comparison; outside the map counts as lit (border depth 0).
void makeShadowComparison(GLuint depth) {
    glTextureParameteri(depth, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTextureParameteri(depth, GL_TEXTURE_COMPARE_FUNC, GL_GEQUAL);
    glTextureParameteri(depth, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(depth, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(depth, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
    glTextureParameteri(depth, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
    const float border[4] = {0, 0, 0, 0};
    glTextureParameterfv(depth, GL_TEXTURE_BORDER_COLOR, border);
}

}  // namespace

LightViewMap::LightViewMap(int resolution, int shadowResolution)
    : resolution_(resolution),
      shadowResolution_(std::max(resolution, shadowResolution)),
      depth_(gl::createTexture2D(GL_DEPTH_COMPONENT32F, resolution, resolution, 1, "light-view depth")),
      position_(gl::createTexture2D(GL_RGBA32F, resolution, resolution, 1, "light-view position")),
      normal_(gl::createTexture2D(GL_RGBA16F, resolution, resolution, 1, "light-view normal")),
      flux_(gl::createTexture2D(GL_RGBA32F, resolution, resolution, 1, "light-view flux")),
      framebuffer_(gl::createFramebuffer("light-view")) {
    const GLuint d = depth_.id();
    makeShadowComparison(d);

    const GLuint fbo = framebuffer_.id();
    glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0, position_.id(), 0);
    glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT1, normal_.id(), 0);
    glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT2, flux_.id(), 0);
    glNamedFramebufferTexture(fbo, GL_DEPTH_ATTACHMENT, d, 0);
    const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2};
    glNamedFramebufferDrawBuffers(fbo, 3, buffers);
    if (glCheckNamedFramebufferStatus(fbo, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        fail("the light-view framebuffer is incomplete on this driver (", resolution, "²)");
    if (shadowResolution_ > resolution_) {
        shadowDepth_ = gl::createTexture2D(GL_DEPTH_COMPONENT32F, shadowResolution_, shadowResolution_, 1,
                                           "shadow map");
        makeShadowComparison(shadowDepth_.id());
        shadowFramebuffer_ = gl::createFramebuffer("shadow map");
        glNamedFramebufferTexture(shadowFramebuffer_.id(), GL_DEPTH_ATTACHMENT, shadowDepth_.id(), 0);
        glNamedFramebufferDrawBuffer(shadowFramebuffer_.id(), GL_NONE);
        if (glCheckNamedFramebufferStatus(shadowFramebuffer_.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
            fail("the shadow-map framebuffer is incomplete on this driver (", shadowResolution_, "²)");
    }
}

LightViewPrograms lightViewPrograms() {
    return {gl::buildProgram({{GL_VERTEX_SHADER, "scene.vert"}, {GL_FRAGMENT_SHADER, "light_view.frag"}}),
            gl::buildProgram({{GL_VERTEX_SHADER, "scene.vert"}}),
            gl::buildProgram({{GL_VERTEX_SHADER, "scene.vert"}, {GL_FRAGMENT_SHADER, "shadow_depth.frag"}})};
}

int lightViewCount(const Light& light) { return light.type == LightType::Point ? kCubeFaces : 1; }

int shadowMapSide(const Light& light, int requested) {
    return light.type == LightType::Point ? std::max(16, requested / 2) : requested;
}

double LightViewMap::maxTexelFlux(const Light& light, const LightViewTransform& transform) {
    return lightQuantity(light) * std::max({light.color.x, light.color.y, light.color.z}) * transform.texelFootprint;
}

std::size_t LightViewMap::bytes() const {
    const std::size_t shadow = shadowDepth_.id() ? std::size_t(shadowResolution_) * shadowResolution_ * 4 : 0;
    return std::size_t(resolution_) * resolution_ * (4 + 16 + 8 + 16) + shadow;
}

void LightViewMap::render(const LightViewPrograms& programs, const GpuScene& gpuScene, const Scene& scene,
                          const Light& light, int face) {
    // Every light reaches the GPU through here (Renderer::setLights validates too, a Scene's own
    // lights are not validated before): nothing non-finite or out of float's range is drawn.
    validateLight(light, "light");
    face_ = face;
    transform_ = lightView(light, scene, resolution_, face);
    gl::beginRasterPass({framebuffer_.id(), resolution_, resolution_, true});
    const float zero[4] = {0, 0, 0, 0};
    for (int i = 0; i < 3; ++i) glClearNamedFramebufferfv(framebuffer_.id(), GL_COLOR, i, zero);
    glClearNamedFramebufferfv(framebuffer_.id(), GL_DEPTH, 0, zero);  // reversed depth: far = 0
    const GLuint p = programs.photons.id();
    glUseProgram(p);
    gl::setUniform(p, "uViewProjection", transform_.view.viewProjection);
    gl::setUniform(p, "uInverseQuantity",
                   float(1.0 / (lightQuantity(light) * std::max({light.color.x, light.color.y, light.color.z}))));
    setLightUniforms(p, light, scene, face);
    gpuScene.draw(p);
    if (shadowDepth_.id()) {
        // Depth only, no colour targets; the same view and the same alpha test.
        gl::beginRasterPass({shadowFramebuffer_.id(), shadowResolution_, shadowResolution_, true});
        glClearNamedFramebufferfv(shadowFramebuffer_.id(), GL_DEPTH, 0, zero);
        auto drawDepth = [&](const gl::Program& program, GpuScene::Materials materials) {
            glUseProgram(program.id());
            gl::setUniform(program.id(), "uViewProjection", transform_.view.viewProjection);
            gpuScene.draw(program.id(), materials);
        };
        drawDepth(programs.shadowOpaque, GpuScene::Materials::Opaque);
        drawDepth(programs.shadowMasked, GpuScene::Materials::Masked);
    }
    gl::endRasterPass();
}

}  // namespace vct
