#pragma once
// The CPU-side scene every part of vct reads: rasterizer, voxelizer and reference path tracer
// all use this one struct, so they see the same triangles, materials, cameras and lights.
//
// Precision: vertex positions are floats *relative to `origin`* (a double-precision world
// point, the centre of the bounds). A model 10⁶ units from the world origin therefore keeps
// full float precision; only cameras and lights (double) are shifted into this frame.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/camera.hpp"
#include "scene/light.hpp"
#include "scene/texture_mapping.hpp"

namespace vct {

struct Vertex {
    glm::vec3 position;  // scene-local: world − Scene::origin
    glm::vec3 normal;    // unit length
    glm::vec2 uv;        // OpenGL convention for every format: (0,0) is the bottom-left of the
                         // image, i.e. the start of the LAST row of Texture::rgba (assimp's
                         // convention; glTF's v is flipped on import). Not wrapped: may leave [0,1].
    glm::vec2 uv1{0.0f};     // second texture-coordinate set (glTF TEXCOORD_1), same convention
    glm::vec3 color{1.0f};   // linear vertex colour (glTF COLOR_0, RGB), multiplies the base colour
};

// Base-colour texture, 8-bit RGBA as stored in the file (sRGB-encoded colour, linear alpha).
struct Texture {
    std::string name;  // file path or "embedded:N", for messages
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;  // width * height * 4, rows top to bottom as in the file
};

enum class AlphaMode { Opaque, Mask };

struct Material {
    std::string name;
    glm::vec3 baseColor{0.8f};      // linear albedo ρ (multiplies the texture)
    int baseColorTexture = -1;      // index into Scene::textures, −1 = none
    TextureMapping baseColorMapping;  // UV set, transform and wrap modes of that texture
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;       // Mask: texel alpha·baseAlpha < cutoff is a hole
    float baseAlpha = 1.0f;
    glm::vec3 emissive{0.0f};       // emitted radiance, W/(m²·sr), linear RGB
};

// Triangles are sorted by material; one range per material that has triangles.
struct DrawRange {
    std::uint32_t firstIndex = 0;  // into Scene::indices
    std::uint32_t indexCount = 0;  // 3 × triangles
    std::uint32_t material = 0;
};

struct Bounds {
    glm::dvec3 min{0.0};
    glm::dvec3 max{0.0};
    glm::dvec3 size() const { return max - min; }
    glm::dvec3 centre() const { return 0.5 * (min + max); }
};

// What the loader did to the input, so that nothing is dropped silently.
struct LoadReport {
    std::size_t sourceTriangles = 0;       // before any clean-up
    std::size_t degenerateTriangles = 0;   // zero area (kept out of the scene, counted)
    std::size_t nonFinitePositions = 0;    // vertices with NaN/Inf position (or beyond ±1e18)
    std::size_t droppedTriangles = 0;      // removed because a vertex position was non-finite
    std::size_t repairedNormals = 0;       // missing, zero or non-finite normals regenerated
    std::size_t repairedUvs = 0;           // non-finite UVs, or beyond ±2^24, set to 0
    std::vector<std::string> missingTextures;
    // What the file asks for that vct does not do (an unsupported extension it uses, skins,
    // animations, single-sided materials, …), one line each, also logged once as a warning.
    std::vector<std::string> unsupportedFeatures;
};

struct Scene {
    std::string name;                 // "cornell", "sponza" or the file name
    std::string sourcePath;           // empty for built-in scenes
    glm::dvec3 origin{0.0};           // world position of the local frame's origin
    Bounds worldBounds;               // double precision, world space

    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;
    std::vector<DrawRange> drawRanges;
    std::vector<Material> materials;
    std::vector<Texture> textures;

    std::vector<Camera> cameras;      // presets; cameras[0] is the default
    std::vector<Light> lights;        // at least one after loading (a default sun if none)
    double exposureEV = 0.0;          // suggested exposure for this scene's default lights

    LoadReport report;

    std::size_t triangleCount() const { return indices.size() / 3; }
    // Bounds in the local frame (float-safe): worldBounds shifted by −origin.
    Bounds localBounds() const { return {worldBounds.min - origin, worldBounds.max - origin}; }
    const Camera& camera(const std::string& presetName) const;  // throws listing the presets
};

}  // namespace vct
