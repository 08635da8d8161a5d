#pragma once
// The light-view maps of the scene's lights, one per light. A map is rendered again only when
// its light changed (Light::operator==) or when what every map shows changed: the geometry, the
// materials or the map resolution (`Key`).
#include <optional>
#include <vector>

#include "render/light_view.hpp"

namespace vct {

class LightViewCache {
public:
    struct Key {
        std::uint64_t geometryVersion = 0, materialsVersion = 0;
        int resolution = 0;
        bool operator==(const Key&) const = default;
    };

    // Renders the maps that are out of date; returns how many it rendered.
    std::uint32_t update(const GpuScene& gpuScene, const Scene& scene, const std::vector<Light>& lights, const Key& key);
    const std::vector<LightViewMap>& maps() const { return maps_; }
    std::size_t bytes() const;
    void clear();

private:
    std::vector<LightViewMap> maps_;
    std::vector<std::optional<Light>> renderedFor_;  // the light each map shows
    std::optional<Key> key_;
};

}  // namespace vct
