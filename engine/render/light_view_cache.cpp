#include "render/light_view_cache.hpp"

namespace vct {

std::uint32_t LightViewCache::update(const GpuScene& gpuScene, const Scene& scene, const std::vector<Light>& lights,
                                     const Key& key) {
    if (key_ != key || views_.size() != lights.size()) {
        // New geometry or materials only change what the maps show: keep their GPU objects and
        // draw them again. New resolutions, or another number of lights, need new maps.
        const bool sameMaps = key_ && key_->resolution == key.resolution &&
                              key_->shadowResolution == key.shadowResolution && views_.size() == lights.size();
        if (!sameMaps) {
            clear();
            views_.resize(lights.size());
        }
        renderedFor_.assign(lights.size(), std::nullopt);
        key_ = key;
    }
    if (!programs_.photons.id()) programs_ = lightViewPrograms();
    std::uint32_t rendered = 0;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        if (renderedFor_[i] == lights[i]) continue;
        // A light that changed type (a spot became a point light) needs another number of maps.
        std::vector<LightViewMap>& maps = views_[i];
        const int count = lightViewCount(lights[i]);
        if (int(maps.size()) != count) {
            maps.clear();
            const int shadowResolution = shadowMapSide(lights[i], key.shadowResolution);
            for (int face = 0; face < count; ++face) maps.emplace_back(key.resolution, shadowResolution);
        }
        for (int face = 0; face < count; ++face) maps[face].render(programs_, gpuScene, scene, lights[i], face);
        renderedFor_[i] = lights[i];
        rendered += std::uint32_t(count);
    }
    return rendered;
}

std::uint32_t LightViewCache::mapCount() const {
    std::uint32_t count = 0;
    for (const std::vector<LightViewMap>& maps : views_) count += std::uint32_t(maps.size());
    return count;
}

std::size_t LightViewCache::bytes() const {
    std::size_t total = 0;
    for (const std::vector<LightViewMap>& maps : views_)
        for (const LightViewMap& map : maps) total += map.bytes();
    return total;
}

void LightViewCache::clear() {
    views_.clear();
    renderedFor_.clear();
    key_.reset();
}

}  // namespace vct
