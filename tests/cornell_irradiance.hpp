#pragma once
// The frame the cone tests measure Cornell's irradiance in: the AOV indirect at 160×120, traced in
// 2×2 blocks through 128³ voxels, with `rays` narrow cones per traced pixel.
#include "pipeline/render_settings.hpp"
#include "render/cone_trace.hpp"

namespace vct::test {

inline RenderSettings cornellIrradianceSettings(int rays = kDefaultNarrowCones) {
    RenderSettings s;
    s.width = 160;
    s.height = 120;
    s.voxelLevels = 7;
    s.lightViewResolution = 1024;
    s.display.aov = Aov::Indirect;
    s.giResolution = GiResolution::Half;
    s.cones.rays = rays;
    return s;
}

}  // namespace vct::test
