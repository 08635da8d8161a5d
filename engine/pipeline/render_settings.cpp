#include "pipeline/render_settings.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "lighting/bounce_gather.hpp"
#include "gl/gl.hpp"
#include "voxel/voxel_grid.hpp"

namespace vct {

ViewMode parseViewMode(const std::string& name) {
    if (name == "lit") return ViewMode::Lit;
    if (name == "voxels") return ViewMode::Voxels;
    if (name == "radiance") return ViewMode::Radiance;
    if (name == "cones") return ViewMode::Cones;
    fail("unknown --view '", name, "'; use lit, voxels, radiance or cones");
}

void validateRenderSettings(const RenderSettings& s) {
    validateImageSize(s.width, s.height);
    if (s.lightViewResolution != 0 && (s.lightViewResolution < 16 || s.lightViewResolution > kMaxImageSide))
        fail("--light-view-res ", s.lightViewResolution, " is out of range; use 16..", kMaxImageSide,
             " (or 0: four texels per voxel side)");
    if (s.shadowMapResolution < 16 || s.shadowMapResolution > kMaxImageSide)
        fail("--shadow-res ", s.shadowMapResolution, " is out of range; use 16..", kMaxImageSide);
    if (s.pcfRadius < 0 || s.pcfRadius > 8) fail("--pcf-radius ", s.pcfRadius, " is out of range; use 0..8");
    if (s.bounces < 1 || s.bounces > kMaxBounces)
        fail("--bounces ", s.bounces, " is out of range; use 1..", kMaxBounces);
    if (s.voxelLevels < kMinVoxelLevels || s.voxelLevels > kMaxVoxelLevels)
        fail("--voxel-levels ", s.voxelLevels, " is out of range; use ", kMinVoxelLevels, "..", kMaxVoxelLevels);
    if (s.voxelViewLevel < 0 || s.voxelViewLevel > s.voxelLevels)
        fail("--voxel-level ", s.voxelViewLevel, " is out of range; use 1..", s.voxelLevels, " (", s.voxelLevels,
             " = the voxels themselves)");
    validateConeSettings(s.cones);
    validateGiFilter(s.giFilter);
    if (!std::isfinite(s.display.giScale) || s.display.giScale < 0.0f)
        fail("--gi-scale ", s.display.giScale, " must be a finite number ≥ 0");
    // 2^EV in float: beyond ±kMaxExposureEV it is 0 or Inf and the tone-mapped image garbage.
    if (!std::isfinite(s.display.exposureEV) || std::abs(s.display.exposureEV) > kMaxExposureEV)
        fail("--exposure ", s.display.exposureEV, " must be a finite number of stops within ±", kMaxExposureEV);
}

void validateRenderSettingsForContext(const RenderSettings& s) {
    validateRenderSettings(s);
    GLint maxTexture = 0, maxViewport[2] = {0, 0};
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxTexture);
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, maxViewport);
    const int maxWidth = std::min(maxTexture, maxViewport[0]);
    const int maxHeight = std::min(maxTexture, maxViewport[1]);
    if (s.width > maxWidth || s.height > maxHeight)
        fail("image size ", s.width, "x", s.height, " is not possible on this GPU; width and height must be within 1..",
             maxWidth, " and 1..", maxHeight);
    if (photonMapResolution(s) > maxTexture)
        fail("--light-view-res ", photonMapResolution(s), " is out of range on this GPU; use 16..", maxTexture);
    const int maxShadow = std::min({int(maxTexture), int(maxViewport[0]), int(maxViewport[1])});
    if (s.shadowMapResolution > maxShadow)
        fail("--shadow-res ", s.shadowMapResolution, " is out of range on this GPU; use 16..", maxShadow);
}

int photonMapResolution(const RenderSettings& s) {
    if (s.lightViewResolution > 0) return s.lightViewResolution;
    return std::clamp(1 << std::clamp(s.voxelLevels + 2, 0, 30), 256, 4096);
}

bool needsOctree(const RenderSettings& s) { return s.view != ViewMode::Lit || s.gi; }

bool needsRadiance(const RenderSettings& s) {
    return s.view == ViewMode::Radiance || s.view == ViewMode::Cones || (s.view == ViewMode::Lit && s.gi);
}

}  // namespace vct
