#include "render/cone_view.hpp"

#include <cmath>

#include "gl/compute.hpp"
#include "render/eye_rays.hpp"

namespace vct {

float viewConeTan(const ConeSettings& settings) {
    const float tan = settings.rays > 0 ? kNarrowConeTan : std::tan(makeConeSet(settings.cones).front().halfAngle);
    return tan * settings.apertureScale;
}

ConeView::ConeView(int width, int height)
    : width_(width),
      height_(height),
      image_(gl::createTexture2D(GL_RGBA32F, width, height, 1, "cone view")),
      program_(gl::buildProgram({{GL_COMPUTE_SHADER, "cone_view.comp"}})) {}

void ConeView::render(const Octree& octree, const RadianceVolume& radiance, const Camera& camera, const Scene& scene,
                      const ConeSettings& settings) {
    ConeSettings cone = settings;
    cone.onlyCone = -1;
    gl::ComputeCall call(program_);
    setConeMarchUniforms(call, octree, radiance, cone);
    call.uniform("uViewTanHalfAngle", viewConeTan(settings));
    setEyeRayUniforms(call, eyeRaysInVoxels(octree, camera, scene, width_, height_));
    call.image(gl::IMAGE_VOXEL_VIEW, image_.id(), GL_WRITE_ONLY, GL_RGBA32F)
        .dispatchImage(width_, height_, GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

}  // namespace vct
