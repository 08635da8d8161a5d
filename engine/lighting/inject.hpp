#pragma once
// inject pass (DESIGN §4 pass 8): photons from every light's light-view map into the voxels, plus
// the emission of emissive voxels, then normalization to area-average outgoing radiance.
#include <vector>

#include "lighting/list_dispatch.hpp"
#include "lighting/radiance_volume.hpp"
#include "render/light_view.hpp"

namespace vct {

class PhotonInjection {
public:
    PhotonInjection();
    // Clears `volume`, injects. `photons` false: only emission (the `--no-photons` toggle).
    void run(const Octree& octree, RadianceVolume& volume, const Scene& scene, const std::vector<Light>& lights,
             const LightViewSets& lightViews, bool photons);

private:
    gl::Program inject_, emissive_, normalize_;
    ListDispatch listDispatch_;
};

// Fixed point, chosen automatically from the lights: the largest possible texel flux of the
// brightest light (LightViewMap::maxTexelFlux) is 2^24 units; this returns the watts of one unit.
// Every light's texels are converted to these units (a dimmer light's texels get fewer), each
// texel adds at most 2^31 units (clamped: albedo > 128), and vct refuses more than 2^33 light-view
// texels in all, so no 64-bit sum can overflow: never wrapped, by construction. Computed in
// double, so any light in kMinLightQuantity..kMaxLightQuantity over any scene size works.
double fluxWattsPerUnit(const std::vector<Light>& lights, const LightViewSets& lightViews);

}  // namespace vct
