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
    : EyeRayView(width, height, "cone view", "cone_view.comp") {}

void ConeView::render(const Octree& octree, const RadianceVolume& radiance, const Camera& camera, const Scene& scene,
                      const ConeSettings& settings) {
    ConeSettings cone = settings;
    cone.onlyCone = -1;
    gl::ComputeCall call(program_);
    setConeMarchUniforms(call, octree, radiance, cone);
    call.uniform("uViewTanHalfAngle", viewConeTan(settings));
    march(call, octree, camera, scene);
}

}  // namespace vct
