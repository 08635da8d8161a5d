#pragma once
// Helpers shared by the stress suite (tests/stress_*.cpp, docs/robustness.md): in-process
// rendering through the real Renderer on OSMesa, scene transforms and image statistics.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "core/image.hpp"
#include "gl/context.hpp"
#include "pipeline/renderer.hpp"
#include "scene/mesh_cleanup.hpp"
#include "scene/scene_loader.hpp"
#include "scene/scene.hpp"

namespace vct::test {

// Small settings that keep a frame well under a second on llvmpipe.
inline RenderSettings smallSettings(int width = 64, int height = 48, int levels = 6, int lightViewRes = 512) {
    RenderSettings s;
    s.width = width;
    s.height = height;
    s.voxelLevels = levels;
    s.lightViewResolution = lightViewRes;
    return s;
}

// One frame of `scene` seen by `camera`; the HDR output of the settings' AOV.
inline ImageF renderInProcess(const Scene& scene, const Camera& camera, const RenderSettings& settings) {
    auto context = gl::createContext(gl::defaultBackend());
    Renderer renderer(scene, settings);
    renderer.renderFrame(camera);
    return renderer.readHdr();
}

inline std::size_t countNonFinite(const std::vector<float>& values) {
    return std::size_t(std::count_if(values.begin(), values.end(), [](float v) { return !std::isfinite(v); }));
}

// Differences between two images of the same size, RGB only.
struct ImageDifference {
    double maxAbs = 0;       // largest |a − b|
    double meanAbs = 0;      // mean |a − b|
    double maxRelative = 0;  // largest |a − b| / max(|b|, floor)
    double meanRelative = 0; // Σ|a − b| / Σ|b|
    double fractionOver = 0; // fraction of values with relative difference above `threshold`
    std::size_t nonFinite = 0;
};

// `floor` keeps near-black pixels from dominating the relative numbers (as relMSE's ε does).
inline ImageDifference compareImages(const ImageF& a, const ImageF& b, double floor, double threshold = 1e-3) {
    ImageDifference d;
    EXPECT_EQ(a.width, b.width);
    EXPECT_EQ(a.height, b.height);
    if (a.rgba.size() != b.rgba.size()) return d;
    double sumAbs = 0, sumB = 0;
    std::size_t n = 0, over = 0;
    for (std::size_t i = 0; i < a.rgba.size(); ++i) {
        if (i % 4 == 3) continue;
        const double x = a.rgba[i], y = b.rgba[i];
        if (!std::isfinite(x) || !std::isfinite(y)) {
            ++d.nonFinite;
            continue;
        }
        const double diff = std::abs(x - y);
        const double relative = diff / std::max(std::abs(y), floor);
        d.maxAbs = std::max(d.maxAbs, diff);
        d.maxRelative = std::max(d.maxRelative, relative);
        over += relative > threshold;
        sumAbs += diff;
        sumB += std::abs(y);
        ++n;
    }
    d.meanAbs = n ? sumAbs / n : 0;
    d.meanRelative = sumB > 0 ? sumAbs / sumB : (sumAbs > 0 ? 1.0 : 0.0);
    d.fractionOver = n ? double(over) / n : 0;
    return d;
}

inline double meanRgb(const ImageF& image) {
    double sum = 0;
    for (std::size_t i = 0; i < image.rgba.size(); ++i)
        if (i % 4 != 3) sum += image.rgba[i];
    return sum / std::max<std::size_t>(1, image.rgba.size() / 4 * 3);
}

inline double maxRgb(const ImageF& image) {
    double m = 0;
    for (std::size_t i = 0; i < image.rgba.size(); ++i)
        if (i % 4 != 3) m = std::max(m, double(image.rgba[i]));
    return m;
}

// The scene's triangles back in world space (double), for rebuilding transformed copies through
// the loaders' own clean-up (buildSceneGeometry: bounds, origin and float positions in double).
inline WorldGeometry worldGeometryOf(const Scene& scene) {
    WorldGeometry g;
    g.parts.push_back({scene.name, 0, 0});
    for (const Vertex& v : scene.vertices) {
        g.positions.push_back(glm::dvec3(v.position) + scene.origin);
        g.normals.push_back(glm::dvec3(v.normal));
        g.uvs.push_back(glm::dvec2(v.uv));
    }
    g.indices = scene.indices;
    g.triangleMaterials.assign(scene.triangleCount(), 0);
    for (const DrawRange& r : scene.drawRanges)
        for (std::uint32_t t = r.firstIndex / 3; t < (r.firstIndex + r.indexCount) / 3; ++t) g.triangleMaterials[t] = r.material;
    return g;
}

// The Cornell box under p → p·s + t: geometry (world-space triangles rebuilt through the loaders'
// clean-up), camera and lights; the spot's intensity × s² so that the image stays the same.
inline Scene transformedCornell(double s, glm::dvec3 t) {
    const Scene unit = makeCornellBox();
    WorldGeometry g = worldGeometryOf(unit);
    for (glm::dvec3& p : g.positions) p = p * s + t;
    Scene scene;
    scene.name = unit.name;
    scene.materials = unit.materials;
    buildSceneGeometry(g, "scaled cornell", false, scene);
    scene.cameras = unit.cameras;
    for (Camera& c : scene.cameras) {
        c.eye = c.eye * s + t;
        c.target = c.target * s + t;
    }
    scene.lights = unit.lights;
    for (Light& l : scene.lights) {
        l.position = l.position * s + t;
        l.intensity *= s * s;
    }
    scene.exposureEV = unit.exposureEV;
    return scene;
}

}  // namespace vct::test
