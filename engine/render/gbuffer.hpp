#pragma once
// G-buffer pass (DESIGN §4 pass 11): rasterizes the scene from the camera into albedo, normal,
// position and emissive targets that the lighting passes read per pixel.
#include "gl/objects.hpp"
#include "render/gpu_scene.hpp"
#include "render/view.hpp"

namespace vct {

class GBuffer {
public:
    GBuffer(int width, int height);
    // `sampleFootprint` (render/pixel_samples.hpp): the share of the pixel's footprint that the
    // texture lookups filter over, 1 for a plain frame, less for later pixel samples.
    void render(const GpuScene& scene, const ViewTransform& camera, float sampleFootprint = 1.0f);

    GLuint albedo() const { return albedo_.id(); }      // RGBA16F linear albedo
    GLuint normal() const { return normal_.id(); }      // RGBA16F unit normal facing the camera
    GLuint position() const { return position_.id(); }  // RGBA32F scene-local position, w=0 sky
    GLuint emissive() const { return emissive_.id(); }  // RGBA32F emitted radiance (any intensity)
    // RGBA16F the triangle's own unit normal facing the camera (the normal() of smooth shading may
    // lean from it: directions behind the triangle receive no light).
    GLuint geometricNormal() const { return geometricNormal_.id(); }
    int width() const { return width_; }
    int height() const { return height_; }
    std::size_t bytes() const;

private:
    int width_, height_;
    gl::Texture albedo_, normal_, position_, emissive_, geometricNormal_, depth_;
    gl::Framebuffer framebuffer_;
    gl::Program program_;
};

}  // namespace vct
