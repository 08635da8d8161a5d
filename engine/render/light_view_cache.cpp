#include "render/light_view_cache.hpp"

namespace vct {

std::uint32_t LightViewCache::update(const GpuScene& gpuScene, const Scene& scene, const std::vector<Light>& lights,
                                     const Key& key) {
    if (key_ != key || maps_.size() != lights.size()) {
        clear();
        for (std::size_t i = 0; i < lights.size(); ++i) maps_.emplace_back(key.resolution);
        renderedFor_.assign(lights.size(), std::nullopt);
        key_ = key;
    }
    std::uint32_t rendered = 0;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        if (renderedFor_[i] == lights[i]) continue;
        maps_[i].render(gpuScene, scene, lights[i]);
        renderedFor_[i] = lights[i];
        ++rendered;
    }
    return rendered;
}

std::size_t LightViewCache::bytes() const {
    std::size_t total = 0;
    for (const LightViewMap& map : maps_) total += map.bytes();
    return total;
}

void LightViewCache::clear() {
    maps_.clear();
    renderedFor_.clear();
    key_.reset();
}

}  // namespace vct
