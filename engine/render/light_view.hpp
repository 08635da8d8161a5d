#pragma once
// Light-view map (DESIGN §4 pass 7): the scene rendered from one light. Its depth is the shadow
// map of the direct pass; position, normal and reflected flux per texel are the photons that the
// GI pipeline injects into the voxel octree.
#include "gl/objects.hpp"
#include "render/gpu_scene.hpp"
#include "render/view.hpp"

namespace vct {

class LightViewMap {
public:
    explicit LightViewMap(int resolution);
    void render(const GpuScene& gpuScene, const Scene& scene, const Light& light);

    GLuint depth() const { return depth_.id(); }        // DEPTH32F, compare mode GL_GEQUAL
    GLuint position() const { return position_.id(); }  // RGBA32F scene-local, w=0 empty
    GLuint normal() const { return normal_.id(); }      // RGBA16F facing the light
    // RGBA32F reflected flux ρ·Φ in W: a texel carries ~1e-4 of the light's intensity, which
    // half floats lose for dim lights (underflow) and bright ones (overflow past 65504).
    GLuint flux() const { return flux_.id(); }
    const LightViewTransform& transform() const { return transform_; }
    int resolution() const { return resolution_; }
    std::size_t bytes() const;

private:
    int resolution_;
    gl::Texture depth_, position_, normal_, flux_;
    gl::Framebuffer framebuffer_;
    gl::Program program_;
    LightViewTransform transform_;
};

}  // namespace vct
