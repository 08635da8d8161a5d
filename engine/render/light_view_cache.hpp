#pragma once
// The light-view maps of the scene's lights: one per light, six (a cube) per point light. A
// light's maps are rendered again only when the light changed (Light::operator==) or when what every map shows changed: the geometry, the
// materials or the map resolutions (`Key`).
#include <optional>
#include <vector>

#include "render/light_view.hpp"

namespace vct {

class LightViewCache {
public:
    struct Key {
        std::uint64_t geometryVersion = 0, materialsVersion = 0;
        int resolution = 0, shadowResolution = 0;
        bool operator==(const Key&) const = default;
    };

    // Renders the maps that are out of date; returns how many maps it rendered.
    std::uint32_t update(const GpuScene& gpuScene, const Scene& scene, const std::vector<Light>& lights, const Key& key);
    const LightViewSets& views() const { return views_; }
    std::uint32_t mapCount() const;
    std::size_t bytes() const;
    void clear();

private:
    LightViewPrograms programs_;  // made on first use
    LightViewSets views_;
    std::vector<std::optional<Light>> renderedFor_;  // the light each set of maps shows
    std::optional<Key> key_;
};

}  // namespace vct
