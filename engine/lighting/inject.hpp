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
             const std::vector<LightViewMap>& lightViews, bool photons);

private:
    gl::Program inject_, emissive_, normalize_;
    ListDispatch listDispatch_;
};

// Fixed-point scale: the largest possible reflected flux of one texel maps to 2^24, so any sum of
// up to 2^40 texels fits the 64-bit accumulators (overflow impossible by construction).
float fluxFixedPointScale(const std::vector<Light>& lights, const std::vector<LightViewMap>& lightViews);

}  // namespace vct
