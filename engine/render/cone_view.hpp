#pragma once
// Debug view `--view cones`: one cone per pixel from the eye through the radiance pools, marched as
// the cones that gather indirect light march (shaders/cone_view.comp). Its image is what such a
// cone brings back from each direction; `--aov direct` of the same camera, averaged over the
// cone's solid angle, is what it should bring back under the one-bounce model.
#include "gl/objects.hpp"
#include "lighting/radiance_volume.hpp"
#include "render/cone_trace.hpp"
#include "render/eye_rays.hpp"
#include "scene/camera.hpp"
#include "scene/scene.hpp"
#include "voxel/octree.hpp"

namespace vct {

// tan of the half-angle of the cone `--view cones` traces: the cone set's cap or a narrow cone,
// times the aperture scale.
float viewConeTan(const ConeSettings& settings);

class ConeView : public EyeRayView {
public:
    ConeView(int width, int height);
    // The cone is as wide as the cap of `settings`' cone set, or with narrow cones (rays > 0) as
    // a narrow cone (viewConeTan), and samples as those cones do.
    void render(const Octree& octree, const RadianceVolume& radiance, const Camera& camera, const Scene& scene,
                const ConeSettings& settings);
};

}  // namespace vct
