// Model import (OBJ+MTL, glTF), bad input, the asset search path, light/camera validation and
// the Sponza scene (skipped when Sponza is not in the asset search path).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include <stb_image_write.h>  // implementation in libstb

#include "core/error.hpp"
#include "scene/scene_loader.hpp"
#include "test_util.hpp"

namespace fs = std::filesystem;

namespace {

using vct::Scene;

void writeText(const fs::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
    ASSERT_TRUE(out.good()) << path;
}

void writeRgbaPng(const fs::path& path, int width, int height,
                  const std::vector<std::uint8_t>& rgba) {
    ASSERT_EQ(rgba.size(), std::size_t(width * height * 4));
    ASSERT_NE(stbi_write_png(path.c_str(), width, height, 4, rgba.data(), width * 4), 0) << path;
}

std::string readBytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

std::string base64(const std::string& bytes) {
    static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    std::size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        const unsigned n = (std::uint8_t(bytes[i]) << 16) | (std::uint8_t(bytes[i + 1]) << 8) |
                           std::uint8_t(bytes[i + 2]);
        out += {table[n >> 18], table[(n >> 12) & 63], table[(n >> 6) & 63], table[n & 63]};
    }
    if (i + 1 == bytes.size()) {
        const unsigned n = std::uint8_t(bytes[i]) << 16;
        out += {table[n >> 18], table[(n >> 12) & 63], '=', '='};
    } else if (i + 2 == bytes.size()) {
        const unsigned n = (std::uint8_t(bytes[i]) << 16) | (std::uint8_t(bytes[i + 1]) << 8);
        out += {table[n >> 18], table[(n >> 12) & 63], table[(n >> 6) & 63], '='};
    }
    return out;
}

template <class T>
void append(std::string& buffer, std::initializer_list<T> values) {
    for (T v : values) buffer.append(reinterpret_cast<const char*>(&v), sizeof v);
}

// Runs `load` and returns the vct::Error message ("" and a test failure if nothing was thrown).
template <class F>
std::string errorOf(F&& load) {
    try {
        load();
    } catch (const vct::Error& e) {
        return e.what();
    } catch (const std::exception& e) {
        ADD_FAILURE() << "expected vct::Error, got another exception: " << e.what();
        return e.what();
    }
    ADD_FAILURE() << "expected vct::Error, nothing was thrown";
    return "";
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

glm::dvec3 world(const Scene& scene, const vct::Vertex& v) {
    return glm::dvec3(v.position) + scene.origin;
}

const vct::Material& materialNamed(const Scene& scene, const std::string& name) {
    for (const vct::Material& m : scene.materials)
        if (m.name == name) return m;
    ADD_FAILURE() << "no material named " << name;
    return scene.materials.at(0);
}

// The unit quad in the z = 0 plane, texture coordinates = positions (OBJ: v up).
const char* kQuadObj = R"(mtllib quad.mtl
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
vt 0 0
vt 1 0
vt 1 1
vt 0 1
usemtl quad
f 1/1 2/2 3/3
f 1/1 3/3 4/4
)";

// 2×2 texture: top row red, green; bottom row blue, white.
const std::vector<std::uint8_t> kTexels = {255, 0, 0, 255, 0, 255, 0, 255,
                                           0, 0, 255, 255, 255, 255, 255, 255};

// ------------------------------------------------------------------------------------------------
// OBJ

TEST(Loader, ObjWithTexture) {
    const fs::path dir = vct::test::testDir();
    writeText(dir / "quad.obj", kQuadObj);
    writeText(dir / "quad.mtl", "newmtl quad\nKd 0.2 0.4 0.6\nmap_Kd tex.png\n");
    writeRgbaPng(dir / "tex.png", 2, 2, kTexels);

    const Scene scene = vct::loadModelFile(dir / "quad.obj");
    EXPECT_EQ(scene.name, "quad.obj");
    EXPECT_EQ(scene.triangleCount(), 2u);
    EXPECT_EQ(scene.vertices.size(), 4u);
    EXPECT_EQ(scene.report.sourceTriangles, 2u);
    EXPECT_EQ(scene.report.degenerateTriangles, 0u);
    EXPECT_TRUE(scene.report.missingTextures.empty());

    ASSERT_EQ(scene.drawRanges.size(), 1u);
    const vct::Material& material = scene.materials.at(scene.drawRanges[0].material);
    EXPECT_EQ(material.name, "quad");
    EXPECT_FLOAT_EQ(material.baseColor.x, 0.2f);
    EXPECT_FLOAT_EQ(material.baseColor.y, 0.4f);
    EXPECT_FLOAT_EQ(material.baseColor.z, 0.6f);
    EXPECT_EQ(material.alphaMode, vct::AlphaMode::Opaque);
    EXPECT_FLOAT_EQ(material.baseAlpha, 1.0f);

    ASSERT_EQ(scene.textures.size(), 1u);
    ASSERT_EQ(material.baseColorTexture, 0);
    const vct::Texture& texture = scene.textures[0];
    EXPECT_EQ(texture.width, 2);
    EXPECT_EQ(texture.height, 2);
    EXPECT_EQ(texture.rgba, kTexels);
    EXPECT_TRUE(contains(texture.name, "tex.png")) << texture.name;

    // Bounds [0,1]² × {0}, origin at the centre.
    EXPECT_EQ(scene.worldBounds.min, glm::dvec3(0.0));
    EXPECT_EQ(scene.worldBounds.max, glm::dvec3(1.0, 1.0, 0.0));
    EXPECT_EQ(scene.origin, glm::dvec3(0.5, 0.5, 0.0));

    // UVs: OpenGL/OBJ convention (Vertex::uv): v = 0 at the bottom of the image, i.e. the
    // last row of Texture::rgba. OBJ's vt arrive unchanged and the texel under each corner is
    // the one the OBJ author meant (vt 0 0 = bottom-left of the image = blue).
    for (const vct::Vertex& v : scene.vertices) {
        const glm::dvec3 p = world(scene, v);
        EXPECT_NEAR(v.uv.x, p.x, 1e-6);
        EXPECT_NEAR(v.uv.y, p.y, 1e-6);
        EXPECT_NEAR(v.normal.z, 1.0f, 1e-6f);  // generated (the OBJ has none), facing +z
        const int tx = std::min(int(v.uv.x * 2), 1), ty = std::min(int((1.0f - v.uv.y) * 2), 1);
        const std::uint8_t* texel = &texture.rgba[(ty * 2 + tx) * 4];
        if (p.x == 0.0 && p.y == 0.0) {
            EXPECT_EQ(texel[2], 255) << "bottom-left must be blue";
        }
        if (p.x == 0.0 && p.y == 1.0) {
            EXPECT_EQ(texel[0], 255) << "top-left must be red";
        }
    }

    // No cameras or lights in an OBJ: a default camera and sun.
    ASSERT_EQ(scene.cameras.size(), 1u);
    EXPECT_EQ(scene.cameras[0].name, "default");
    EXPECT_EQ(scene.cameras[0].target, scene.worldBounds.centre());
    EXPECT_GT(scene.cameras[0].eye.z, scene.worldBounds.max.z);
    EXPECT_GT(scene.cameras[0].eye.y, scene.cameras[0].target.y);
    EXPECT_NO_THROW(vct::validateCamera(scene.cameras[0]));
    ASSERT_EQ(scene.lights.size(), 1u);
    EXPECT_EQ(scene.lights[0].type, vct::LightType::Directional);
    const glm::dvec3 sun = glm::normalize(glm::dvec3(-0.3, -1.0, -0.2));
    EXPECT_NEAR(glm::distance(scene.lights[0].direction, sun), 0.0, 1e-12);
    EXPECT_DOUBLE_EQ(scene.lights[0].irradiance, 3.0);
    EXPECT_DOUBLE_EQ(scene.exposureEV, 0.0);
}

TEST(Loader, ObjTextureSharedByMaterialsIsDecodedOnce) {
    const fs::path dir = vct::test::testDir();
    writeText(dir / "two.obj", R"(mtllib two.mtl
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0 0 1
v 1 0 1
v 1 1 1
usemtl a
f 1 2 3
f 1 3 4
usemtl b
f 5 6 7
)");
    writeText(dir / "two.mtl",
              "newmtl a\nKd 1 1 1\nmap_Kd tex.png\nnewmtl b\nKd 0.5 0.5 0.5\nmap_Kd tex.png\n");
    writeRgbaPng(dir / "tex.png", 2, 2, kTexels);
    const Scene scene = vct::loadModelFile(dir / "two.obj");
    EXPECT_EQ(scene.triangleCount(), 3u);
    ASSERT_EQ(scene.textures.size(), 1u);
    EXPECT_EQ(materialNamed(scene, "a").baseColorTexture, 0);
    EXPECT_EQ(materialNamed(scene, "b").baseColorTexture, 0);
    // Unused materials (assimp's OBJ "DefaultMaterial") are not kept; one range per material.
    EXPECT_EQ(scene.materials.size(), 2u);
    ASSERT_EQ(scene.drawRanges.size(), 2u);
    EXPECT_EQ(scene.drawRanges[0].indexCount + scene.drawRanges[1].indexCount, 9u);
    EXPECT_EQ(scene.materials[scene.drawRanges[0].material].name, "a");
    EXPECT_EQ(scene.drawRanges[0].indexCount, 6u);
}

TEST(Loader, ObjAlphaMasks) {
    const fs::path dir = vct::test::testDir();
    writeText(dir / "masks.obj", R"(mtllib masks.mtl
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
vt 0 0
vt 1 0
vt 1 1
usemtl opaque
f 1/1 2/2 3/3
usemtl alphaTexture
f 1/1 3/3 4/2
usemtl separateMask
f 2/1 3/2 4/3
usemtl resampledMask
f 1/1 2/2 4/3
)");
    writeText(dir / "masks.mtl", R"(newmtl opaque
map_Kd tex.png
newmtl alphaTexture
map_Kd holes.png
newmtl separateMask
map_Kd tex.png
map_d mask.png
newmtl resampledMask
map_Kd tex.png
map_d bigmask.png
)");
    writeRgbaPng(dir / "tex.png", 2, 2, kTexels);
    std::vector<std::uint8_t> holes = kTexels;
    holes[3] = 0;  // top-left texel transparent
    writeRgbaPng(dir / "holes.png", 2, 2, holes);
    // Grey masks (1 channel): the value becomes the base texture's alpha.
    const std::uint8_t mask[4] = {0, 255, 128, 255};
    ASSERT_NE(stbi_write_png((dir / "mask.png").c_str(), 2, 2, 1, mask, 2), 0);
    std::vector<std::uint8_t> bigMask(16);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) bigMask[y * 4 + x] = (x < 2 && y < 2) ? 0 : 255;
    ASSERT_NE(stbi_write_png((dir / "bigmask.png").c_str(), 4, 4, 1, bigMask.data(), 4), 0);

    const Scene scene = vct::loadModelFile(dir / "masks.obj");
    const vct::Material& opaque = materialNamed(scene, "opaque");
    const vct::Material& alphaTexture = materialNamed(scene, "alphaTexture");
    const vct::Material& separate = materialNamed(scene, "separateMask");
    const vct::Material& resampled = materialNamed(scene, "resampledMask");
    EXPECT_EQ(opaque.alphaMode, vct::AlphaMode::Opaque);
    EXPECT_EQ(alphaTexture.alphaMode, vct::AlphaMode::Mask);
    EXPECT_FLOAT_EQ(alphaTexture.alphaCutoff, 0.5f);
    EXPECT_EQ(separate.alphaMode, vct::AlphaMode::Mask);
    EXPECT_EQ(resampled.alphaMode, vct::AlphaMode::Mask);

    // Four distinct textures: tex, holes, tex+mask, tex+resampled mask; the plain tex.png is
    // shared with nothing else, and the folded ones do not alter it.
    ASSERT_EQ(scene.textures.size(), 4u);
    const vct::Texture& plain = scene.textures.at(opaque.baseColorTexture);
    EXPECT_EQ(plain.rgba, kTexels);
    const vct::Texture& folded = scene.textures.at(separate.baseColorTexture);
    ASSERT_EQ(folded.rgba.size(), 16u);
    for (int i = 0; i < 4; ++i) {
        EXPECT_EQ(folded.rgba[4 * i + 3], mask[i]) << "texel " << i;
        EXPECT_EQ(folded.rgba[4 * i + 0], kTexels[4 * i + 0]) << "colour kept, texel " << i;
    }
    const vct::Texture& foldedResampled = scene.textures.at(resampled.baseColorTexture);
    EXPECT_EQ(foldedResampled.width, 2);
    EXPECT_EQ(foldedResampled.rgba[3], 0);     // top-left quarter of the 4×4 mask is 0
    EXPECT_EQ(foldedResampled.rgba[7], 255);
    EXPECT_EQ(foldedResampled.rgba[15], 255);
}

// ------------------------------------------------------------------------------------------------
// glTF

// One quad mesh instanced twice under a node 10⁶ units from the origin, a masked emissive
// material, a camera and a spot light (KHR_lights_punctual).
std::string farAwayGltf() {
    std::string buffer;
    append<float>(buffer, {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0});  // positions
    append<float>(buffer, {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1});  // normals
    append<float>(buffer, {0, 0, 1, 0, 1, 1, 0, 1});              // uvs (glTF: v down)
    append<std::uint16_t>(buffer, {0, 1, 2, 0, 2, 3});
    return R"({
  "asset": {"version": "2.0"},
  "extensionsUsed": ["KHR_lights_punctual"],
  "extensions": {"KHR_lights_punctual": {"lights": [
    {"name": "SpotData", "type": "spot", "color": [1, 0.5, 0.5], "intensity": 5,
     "spot": {"innerConeAngle": 0.3, "outerConeAngle": 0.6}}]}},
  "scene": 0,
  "scenes": [{"nodes": [0, 3, 4]}],
  "nodes": [
    {"name": "Root", "translation": [1000000, 0, 0], "children": [1, 2]},
    {"name": "QuadA", "mesh": 0, "rotation": [0, 1, 0, 0], "scale": [2, 3, 1]},
    {"name": "QuadB", "mesh": 0, "translation": [0, 0, 10], "scale": [-1, 1, 1]},
    {"name": "Cam", "camera": 0, "translation": [1000000, 1, 5]},
    {"name": "Spot", "translation": [1000000, 2, 0],
     "rotation": [-0.70710678, 0, 0, 0.70710678],
     "extensions": {"KHR_lights_punctual": {"light": 0}}}
  ],
  "cameras": [{"name": "CamData", "type": "perspective",
               "perspective": {"yfov": 0.6, "aspectRatio": 1.5, "znear": 0.1, "zfar": 100}}],
  "meshes": [{"name": "quad", "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1,
              "TEXCOORD_0": 2}, "indices": 3, "material": 0}]}],
  "materials": [{"name": "Masked",
                 "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.25, 0.125, 0.8]},
                 "alphaMode": "MASK", "alphaCutoff": 0.3, "emissiveFactor": [1, 0.5, 0]}],
  "buffers": [{"byteLength": 140,
               "uri": "data:application/octet-stream;base64,)" +
           base64(buffer) + R"("}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 128},
                  {"buffer": 0, "byteOffset": 128, "byteLength": 12}],
  "accessors": [
    {"bufferView": 0, "byteOffset": 0, "componentType": 5126, "count": 4, "type": "VEC3",
     "min": [0, 0, 0], "max": [1, 1, 0]},
    {"bufferView": 0, "byteOffset": 48, "componentType": 5126, "count": 4, "type": "VEC3"},
    {"bufferView": 0, "byteOffset": 96, "componentType": 5126, "count": 4, "type": "VEC2"},
    {"bufferView": 1, "byteOffset": 0, "componentType": 5123, "count": 6, "type": "SCALAR"}
  ]
})";
}

TEST(Loader, GltfFlattensNodesInDoublePrecision) {
    const fs::path dir = vct::test::testDir();
    writeText(dir / "far.gltf", farAwayGltf());
    const Scene scene = vct::loadModelFile(dir / "far.gltf");

    // Two instances of the 2-triangle mesh.
    EXPECT_EQ(scene.triangleCount(), 4u);
    EXPECT_EQ(scene.report.sourceTriangles, 4u);
    // QuadA: scale (2,3,1), rotate 180° about y, move by 10⁶ → x ∈ [10⁶−2, 10⁶], y ∈ [0,3], z 0.
    // QuadB: mirror x, move to z = 10 → x ∈ [10⁶−1, 10⁶], y ∈ [0,1], z = 10.
    EXPECT_DOUBLE_EQ(scene.worldBounds.min.x, 999998.0);
    EXPECT_DOUBLE_EQ(scene.worldBounds.max.x, 1000000.0);
    EXPECT_DOUBLE_EQ(scene.worldBounds.min.y, 0.0);
    EXPECT_DOUBLE_EQ(scene.worldBounds.max.y, 3.0);
    EXPECT_NEAR(scene.worldBounds.min.z, 0.0, 1e-9);
    EXPECT_NEAR(scene.worldBounds.max.z, 10.0, 1e-9);
    EXPECT_NEAR(scene.origin.x, 999999.0, 1e-9);
    // Local positions are small and exact: float keeps full precision near 0.
    for (const vct::Vertex& v : scene.vertices) {
        EXPECT_LE(std::abs(v.position.x), 1.0f);
        EXPECT_LE(std::abs(v.position.y), 1.5f);
        EXPECT_LE(std::abs(v.position.z), 5.0f);
        EXPECT_EQ(v.position.x, std::round(v.position.x)) << "x must be an exact integer";
    }
    // Normals follow the node transforms (inverse transpose), windings stay counter-clockwise.
    int facingMinusZ = 0, facingPlusZ = 0;
    for (std::size_t i = 0; i < scene.indices.size(); i += 3) {
        const auto& a = scene.vertices[scene.indices[i]];
        const auto& b = scene.vertices[scene.indices[i + 1]];
        const auto& c = scene.vertices[scene.indices[i + 2]];
        const glm::vec3 face = glm::cross(b.position - a.position, c.position - a.position);
        EXPECT_GT(glm::dot(face, a.normal), 0.0f) << "triangle " << i / 3;
        EXPECT_NEAR(glm::length(a.normal), 1.0f, 1e-6f);
        (a.normal.z < 0 ? facingMinusZ : facingPlusZ)++;
    }
    EXPECT_EQ(facingMinusZ, 2);  // QuadA, rotated 180°
    EXPECT_EQ(facingPlusZ, 2);   // QuadB, mirrored in x only
    // glTF's v runs down the image; in vct's (OpenGL) convention it runs up: glTF uv (0, 0) on
    // vertex 0 of each quad arrives as (0, 1).
    int atTopLeft = 0;
    for (const vct::Vertex& v : scene.vertices)
        if (v.uv == glm::vec2(0.0f, 1.0f)) ++atTopLeft;
    EXPECT_EQ(atTopLeft, 2);
}

TEST(Loader, GltfMaterialCameraLight) {
    const fs::path dir = vct::test::testDir();
    writeText(dir / "far.gltf", farAwayGltf());
    const Scene scene = vct::loadModelFile(dir / "far.gltf");

    ASSERT_EQ(scene.materials.size(), 1u);
    const vct::Material& m = scene.materials[0];
    EXPECT_EQ(m.name, "Masked");
    EXPECT_FLOAT_EQ(m.baseColor.x, 0.5f);
    EXPECT_FLOAT_EQ(m.baseColor.y, 0.25f);
    EXPECT_FLOAT_EQ(m.baseColor.z, 0.125f);
    EXPECT_FLOAT_EQ(m.baseAlpha, 0.8f);
    EXPECT_EQ(m.alphaMode, vct::AlphaMode::Mask);
    EXPECT_FLOAT_EQ(m.alphaCutoff, 0.3f);
    // emissiveFactor (assimp 5.2 ignores KHR_materials_emissive_strength, so it is not used
    // here; where assimp reads it, it multiplies in through AI_MATKEY_EMISSIVE_INTENSITY).
    EXPECT_FLOAT_EQ(m.emissive.x, 1.0f);
    EXPECT_FLOAT_EQ(m.emissive.y, 0.5f);
    EXPECT_FLOAT_EQ(m.emissive.z, 0.0f);
    EXPECT_EQ(m.baseColorTexture, -1);

    // The camera preset takes its node's name; it sits at the node's origin (not twice its
    // translation) and looks down the node's −z.
    ASSERT_EQ(scene.cameras.size(), 1u);
    const vct::Camera& camera = scene.camera("Cam");
    EXPECT_NEAR(camera.eye.x, 1000000.0, 1e-9);
    EXPECT_NEAR(camera.eye.y, 1.0, 1e-9);
    EXPECT_NEAR(camera.eye.z, 5.0, 1e-9);
    const glm::dvec3 forward = glm::normalize(camera.target - camera.eye);
    EXPECT_NEAR(forward.z, -1.0, 1e-9);
    EXPECT_NEAR(camera.up.y, 1.0, 1e-9);
    EXPECT_NEAR(camera.fovYDeg, glm::degrees(0.6), 1e-4);  // glTF yfov, whatever the aspect

    // Spot light: position and direction from its node, intensity and colour split again.
    ASSERT_EQ(scene.lights.size(), 1u);
    const vct::Light& light = scene.lights[0];
    EXPECT_EQ(light.type, vct::LightType::Spot);
    EXPECT_NEAR(light.position.x, 1000000.0, 1e-9);
    EXPECT_NEAR(light.position.y, 2.0, 1e-9);
    EXPECT_NEAR(light.position.z, 0.0, 1e-9);
    EXPECT_NEAR(light.direction.y, -1.0, 1e-6);
    EXPECT_NEAR(light.intensity, 5.0, 1e-6);
    EXPECT_NEAR(light.color.x, 1.0, 1e-6);
    EXPECT_NEAR(light.color.y, 0.5, 1e-6);
    EXPECT_NEAR(light.innerAngleDeg, glm::degrees(0.3), 1e-4);
    EXPECT_NEAR(light.outerAngleDeg, glm::degrees(0.6), 1e-4);
    // Exposure from the light: E = 5 / d², d = |light − bounds centre|; albedo 0.5 → ≈ 0.8.
    const double d2 = glm::dot(light.position - scene.worldBounds.centre(),
                               light.position - scene.worldBounds.centre());
    const double exposed = 0.5 / M_PI * 5.0 / d2 * std::exp2(scene.exposureEV);
    EXPECT_GT(exposed, 0.8 / std::sqrt(2.0) - 1e-9);
    EXPECT_LT(exposed, 0.8 * std::sqrt(2.0) + 1e-9);
}

TEST(Loader, GltfEmbeddedTexture) {
    const fs::path dir = vct::test::testDir();
    writeRgbaPng(dir / "tex.png", 2, 2, kTexels);
    const std::string png = readBytes(dir / "tex.png");
    fs::remove(dir / "tex.png");  // only the embedded copy exists
    std::string buffer;
    append<float>(buffer, {0, 0, 0, 1, 0, 0, 1, 1, 0});
    append<float>(buffer, {0, 1, 1, 1, 1, 0});
    writeText(dir / "embedded.gltf", R"({
  "asset": {"version": "2.0"},
  "scenes": [{"nodes": [0]}], "scene": 0,
  "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "material": 0}]}],
  "materials": [{"name": "tex", "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],
  "textures": [{"source": 0}],
  "images": [{"uri": "data:image/png;base64,)" + base64(png) + R"("}],
  "buffers": [{"byteLength": 60, "uri": "data:application/octet-stream;base64,)" +
                                      base64(buffer) + R"("}],
  "bufferViews": [{"buffer": 0, "byteLength": 60}],
  "accessors": [
    {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
     "min": [0, 0, 0], "max": [1, 1, 0]},
    {"bufferView": 0, "byteOffset": 36, "componentType": 5126, "count": 3, "type": "VEC2"}]
})");
    const Scene scene = vct::loadModelFile(dir / "embedded.gltf");
    EXPECT_EQ(scene.triangleCount(), 1u);
    EXPECT_EQ(scene.report.repairedNormals, 0u) << "assimp generates the missing normals";
    ASSERT_EQ(scene.textures.size(), 1u);
    EXPECT_EQ(scene.materials.at(0).baseColorTexture, 0);
    EXPECT_EQ(scene.textures[0].rgba, kTexels);
    EXPECT_TRUE(contains(scene.textures[0].name, "embedded")) << scene.textures[0].name;
    EXPECT_TRUE(scene.report.missingTextures.empty());
    EXPECT_EQ(scene.materials[0].alphaMode, vct::AlphaMode::Opaque);  // glTF default OPAQUE
}

// ------------------------------------------------------------------------------------------------
// Bad input

TEST(Loader, MissingFile) {
    const fs::path path = vct::test::testDir() / "nothing-here.gltf";
    const std::string message = errorOf([&] { vct::loadModelFile(path); });
    EXPECT_TRUE(contains(message, path.string())) << message;
    EXPECT_TRUE(contains(message, "not found")) << message;
    EXPECT_TRUE(contains(message, "--scene cornell|sponza")) << message;
    // Through loadScene too.
    EXPECT_TRUE(contains(errorOf([&] { vct::loadScene(path.string()); }), "not found"));
    EXPECT_TRUE(contains(errorOf([&] { vct::loadScene(""); }), "cornell"));
}

TEST(Loader, FolderInsteadOfFile) {
    const fs::path dir = vct::test::testDir();
    const std::string message = errorOf([&] { vct::loadModelFile(dir); });
    EXPECT_TRUE(contains(message, dir.string())) << message;
}

TEST(Loader, GarbageObj) {
    const fs::path dir = vct::test::testDir();
    std::string junk;
    std::uint32_t state = 12345;
    for (int i = 0; i < 4096; ++i) {
        state = state * 1664525u + 1013904223u;
        junk.push_back(static_cast<char>(state >> 24));
    }
    writeText(dir / "junk.obj", junk);
    const std::string message = errorOf([&] { vct::loadModelFile(dir / "junk.obj"); });
    EXPECT_TRUE(contains(message, (dir / "junk.obj").string())) << message;
}

TEST(Loader, TruncatedGltf) {
    const fs::path dir = vct::test::testDir();
    const std::string full = farAwayGltf();
    writeText(dir / "cut.gltf", full.substr(0, full.size() / 2));
    const std::string message = errorOf([&] { vct::loadModelFile(dir / "cut.gltf"); });
    EXPECT_TRUE(contains(message, (dir / "cut.gltf").string())) << message;
    EXPECT_TRUE(contains(message, "cannot read model")) << message;
}

TEST(Loader, UnsupportedFormat) {
    const fs::path dir = vct::test::testDir();
    writeText(dir / "notes.txt", "this is not a model\n");
    const std::string message = errorOf([&] { vct::loadModelFile(dir / "notes.txt"); });
    EXPECT_TRUE(contains(message, (dir / "notes.txt").string())) << message;
}

TEST(Loader, NonFinitePositions) {
    const fs::path dir = vct::test::testDir();
    writeText(dir / "nan.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv nan 1 0\nf 1 2 3\nf 1 3 4\n");
    const std::string message = errorOf([&] { vct::loadModelFile(dir / "nan.obj"); });
    EXPECT_TRUE(contains(message, "non-finite")) << message;
    EXPECT_TRUE(contains(message, "1 vertices")) << message;
    EXPECT_TRUE(contains(message, "vertex ")) << message;
    EXPECT_TRUE(contains(message, "--sanitize")) << message;
    EXPECT_TRUE(contains(message, (dir / "nan.obj").string())) << message;

    vct::LoadOptions options;
    options.sanitize = true;
    const Scene scene = vct::loadModelFile(dir / "nan.obj", options);
    EXPECT_EQ(scene.report.sourceTriangles, 2u);
    EXPECT_EQ(scene.report.nonFinitePositions, 1u);
    EXPECT_EQ(scene.report.droppedTriangles, 1u);
    EXPECT_EQ(scene.triangleCount(), 1u);
    EXPECT_EQ(scene.vertices.size(), 3u) << "the NaN vertex must not reach the renderer";
    for (const vct::Vertex& v : scene.vertices) {
        EXPECT_TRUE(std::isfinite(v.position.x) && std::isfinite(v.position.y));
        EXPECT_TRUE(std::isfinite(v.normal.x) && std::isfinite(v.normal.z));
        EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-6f);
    }
    EXPECT_EQ(scene.worldBounds.max, glm::dvec3(1.0, 1.0, 0.0));
}

TEST(Loader, NonFiniteVertexIsNotMergedAway) {
    // assimp's JoinIdenticalVertices compares with epsilons, which NaN passes: without care this
    // NaN vertex is merged into a neighbour and a wrong triangle renders silently.
    const fs::path dir = vct::test::testDir();
    writeText(dir / "merge.obj", R"(v -1 0 1
v 1 0 1
v 1 0 -1
v -1 0 1
v 1 0 -1
v -1 0 -1
v 0 1 0
v nan 1 0
v 0 1 1
f 1 2 3
f 4 5 6
f 7 8 9
)");
    const std::string message = errorOf([&] { vct::loadModelFile(dir / "merge.obj"); });
    EXPECT_TRUE(contains(message, "1 vertices have non-finite")) << message;

    vct::LoadOptions options;
    options.sanitize = true;
    const Scene scene = vct::loadModelFile(dir / "merge.obj", options);
    EXPECT_EQ(scene.report.sourceTriangles, 3u);
    EXPECT_EQ(scene.report.droppedTriangles, 1u);
    EXPECT_EQ(scene.report.nonFinitePositions, 1u);
    EXPECT_EQ(scene.triangleCount(), 2u);
    EXPECT_EQ(scene.vertices.size(), 4u);
    EXPECT_EQ(scene.worldBounds.max.y, 0.0) << "only the floor is left";
    EXPECT_EQ(scene.report.repairedNormals, 0u);

    // Every triangle broken: nothing left, said so.
    writeText(dir / "allnan.obj", "v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n");
    const std::string none = errorOf([&] { vct::loadModelFile(dir / "allnan.obj", options); });
    EXPECT_TRUE(contains(none, "no triangles")) << none;
    EXPECT_TRUE(contains(none, "non-finite")) << none;
}

TEST(Loader, InfinityInAnInstancedGltfIsCountedOnce) {
    const fs::path dir = vct::test::testDir();
    std::string buffer;
    append<float>(buffer, {0, 0, 0, 1, 0, 0, 1, 1, 0, INFINITY, 1, 0});
    append<std::uint16_t>(buffer, {0, 1, 2, 0, 2, 3});
    writeText(dir / "inf.gltf", R"({
  "asset": {"version": "2.0"},
  "scenes": [{"nodes": [0, 1]}], "scene": 0,
  "nodes": [{"mesh": 0}, {"mesh": 0, "translation": [0, 0, 5]}],
  "meshes": [{"name": "broken", "primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
  "buffers": [{"byteLength": 60, "uri": "data:application/octet-stream;base64,)" +
                                  base64(buffer) + R"("}],
  "bufferViews": [{"buffer": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 12}],
  "accessors": [
    {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
     "min": [0, 0, 0], "max": [1, 1, 0]},
    {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"}]
})");
    const std::string message = errorOf([&] { vct::loadModelFile(dir / "inf.gltf"); });
    EXPECT_TRUE(contains(message, "1 vertices have non-finite")) << message;
    EXPECT_TRUE(contains(message, "mesh 'broken' vertex 3")) << message;

    vct::LoadOptions options;
    options.sanitize = true;
    const Scene scene = vct::loadModelFile(dir / "inf.gltf", options);
    EXPECT_EQ(scene.report.nonFinitePositions, 1u);
    EXPECT_EQ(scene.report.droppedTriangles, 2u);  // one per instance
    EXPECT_EQ(scene.triangleCount(), 2u);
    EXPECT_NEAR(scene.worldBounds.max.z, 5.0, 1e-12);
}

TEST(Loader, DegenerateTriangles) {
    const fs::path dir = vct::test::testDir();
    // Collinear, repeated vertex, and one good triangle.
    writeText(dir / "some.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 3\nf 1 1 2\nf 1 2 4\n");
    const Scene scene = vct::loadModelFile(dir / "some.obj");
    EXPECT_EQ(scene.report.sourceTriangles, 3u);
    EXPECT_EQ(scene.report.degenerateTriangles, 2u);
    EXPECT_EQ(scene.triangleCount(), 1u);
    EXPECT_EQ(scene.worldBounds.max, glm::dvec3(1.0, 1.0, 0.0)) << "bounds of kept triangles";

    writeText(dir / "flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\nf 1 1 2\n");
    const std::string message = errorOf([&] { vct::loadModelFile(dir / "flat.obj"); });
    EXPECT_TRUE(contains(message, "no triangles")) << message;
    EXPECT_TRUE(contains(message, "2 have zero area")) << message;
    EXPECT_TRUE(contains(message, (dir / "flat.obj").string())) << message;
}

TEST(Loader, OnlyPointsAndLines) {
    const fs::path dir = vct::test::testDir();
    writeText(dir / "lines.obj", "v 0 0 0\nv 1 0 0\nv 2 1 0\nl 1 2\nl 2 3\np 1\n");
    const std::string message = errorOf([&] { vct::loadModelFile(dir / "lines.obj"); });
    EXPECT_TRUE(contains(message, "no triangles")) << message;
}

TEST(Loader, MissingAndUndecodableTextures) {
    const fs::path dir = vct::test::testDir();
    writeText(dir / "quad.obj", kQuadObj);
    writeText(dir / "quad.mtl", "newmtl quad\nKd 0.2 0.4 0.6\nmap_Kd nothere.png\n");
    const Scene scene = vct::loadModelFile(dir / "quad.obj");
    EXPECT_EQ(scene.triangleCount(), 2u);
    ASSERT_EQ(scene.report.missingTextures.size(), 1u);
    EXPECT_TRUE(contains(scene.report.missingTextures[0], "nothere.png"));
    EXPECT_EQ(scene.materials.at(0).baseColorTexture, -1);
    EXPECT_TRUE(scene.textures.empty());
    EXPECT_FLOAT_EQ(scene.materials.at(0).baseColor.y, 0.4f);

    writeText(dir / "quad.mtl", "newmtl quad\nmap_Kd broken.png\n");
    writeText(dir / "broken.png", "not a png at all");
    const Scene broken = vct::loadModelFile(dir / "quad.obj");
    ASSERT_EQ(broken.report.missingTextures.size(), 1u);
    EXPECT_TRUE(contains(broken.report.missingTextures[0], "broken.png"));
    EXPECT_EQ(broken.materials.at(0).baseColorTexture, -1);
}

TEST(Loader, TexturePathsWrittenOnAnotherSystem) {
    const fs::path dir = vct::test::testDir();
    fs::create_directories(dir / "textures");
    writeText(dir / "quad.obj", kQuadObj);
    writeText(dir / "quad.mtl", "newmtl quad\nmap_Kd textures\\tex.png\n");
    writeRgbaPng(dir / "textures" / "tex.png", 2, 2, kTexels);
    const Scene scene = vct::loadModelFile(dir / "quad.obj");
    EXPECT_TRUE(scene.report.missingTextures.empty());
    EXPECT_EQ(scene.materials.at(0).baseColorTexture, 0);
}

TEST(Loader, RepairsNormalsAndUvs) {
    // glTF, because assimp's OBJ parser reads "nan" texture coordinates as 0.
    const fs::path dir = vct::test::testDir();
    std::string buffer;
    append<float>(buffer, {0, 0, 0, 1, 0, 0, 1, 1, 0});        // positions
    append<float>(buffer, {0, 0, 0, 0, 0, 1, NAN, 0, 1});      // zero, good, NaN normal
    append<float>(buffer, {0, 0, NAN, 0, 1, INFINITY});        // uv 1 and 2 broken
    writeText(dir / "bad.gltf", R"({
  "asset": {"version": "2.0"},
  "scenes": [{"nodes": [0]}], "scene": 0,
  "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}}]}],
  "buffers": [{"byteLength": 96, "uri": "data:application/octet-stream;base64,)" +
                                  base64(buffer) + R"("}],
  "bufferViews": [{"buffer": 0, "byteLength": 96}],
  "accessors": [
    {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
     "min": [0, 0, 0], "max": [1, 1, 0]},
    {"bufferView": 0, "byteOffset": 36, "componentType": 5126, "count": 3, "type": "VEC3"},
    {"bufferView": 0, "byteOffset": 72, "componentType": 5126, "count": 3, "type": "VEC2"}]
})");
    const Scene scene = vct::loadModelFile(dir / "bad.gltf");
    EXPECT_EQ(scene.triangleCount(), 1u);
    EXPECT_EQ(scene.report.repairedNormals, 2u);
    EXPECT_EQ(scene.report.repairedUvs, 2u);
    for (const vct::Vertex& v : scene.vertices) {
        EXPECT_NEAR(v.normal.z, 1.0f, 1e-6f);
        EXPECT_TRUE(std::isfinite(v.uv.x) && std::isfinite(v.uv.y));
    }
}

TEST(Loader, OutOfRangeFaceIndexDoesNotCrash) {
    const fs::path dir = vct::test::testDir();
    writeText(dir / "oob.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 30\nf 1 2 3\n");
    try {
        const Scene scene = vct::loadModelFile(dir / "oob.obj");
        EXPECT_LE(scene.triangleCount(), 1u);  // a clean load is fine too
    } catch (const vct::Error& e) {
        EXPECT_TRUE(contains(e.what(), (dir / "oob.obj").string())) << e.what();
    }

    // glTF indices past the end of the vertex accessor.
    std::string buffer;
    append<float>(buffer, {0, 0, 0, 1, 0, 0, 1, 1, 0});
    append<std::uint16_t>(buffer, {0, 1, 2, 0, 2, 999});
    writeText(dir / "oob.gltf", R"({
  "asset": {"version": "2.0"},
  "scenes": [{"nodes": [0]}], "scene": 0,
  "nodes": [{"mesh": 0}],
  "meshes": [{"name": "oob", "primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
  "buffers": [{"byteLength": 48, "uri": "data:application/octet-stream;base64,)" +
                                  base64(buffer) + R"("}],
  "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 12}],
  "accessors": [
    {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
     "min": [0, 0, 0], "max": [1, 1, 0]},
    {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"}]
})");
    try {
        const Scene scene = vct::loadModelFile(dir / "oob.gltf");
        EXPECT_LE(scene.triangleCount(), 1u);
    } catch (const vct::Error& e) {
        EXPECT_TRUE(contains(e.what(), (dir / "oob.gltf").string())) << e.what();
    }

    // Absurd counts: an accessor claiming 10⁹ vertices in a 36-byte buffer.
    std::string absurd = readBytes(dir / "oob.gltf");
    absurd.replace(absurd.find("\"count\": 3"), 10, "\"count\": 1000000000");
    writeText(dir / "absurd.gltf", absurd);
    try {
        vct::loadModelFile(dir / "absurd.gltf");
    } catch (const vct::Error& e) {
        EXPECT_TRUE(contains(e.what(), (dir / "absurd.gltf").string())) << e.what();
    }
}

// ------------------------------------------------------------------------------------------------
// Asset search path

class EnvironmentVariable {
public:
    EnvironmentVariable(const char* name, const std::string& value) : name_(name) {
        if (const char* old = std::getenv(name)) old_ = old;
        setenv(name, value.c_str(), 1);
    }
    ~EnvironmentVariable() {
        if (old_)
            setenv(name_, old_->c_str(), 1);
        else
            unsetenv(name_);
    }

private:
    const char* name_;
    std::optional<std::string> old_;
};

TEST(Asset, SearchPathPrefersVctAssetDir) {
    const fs::path dir = vct::test::testDir();
    fs::create_directories(dir / "sub");
    writeText(dir / "sub" / "thing.txt", "x");
    {
        EnvironmentVariable env("VCT_ASSET_DIR", dir.string());
        const auto found = vct::findAsset("sub/thing.txt");
        ASSERT_TRUE(found.has_value());
        EXPECT_TRUE(fs::equivalent(*found, dir / "sub" / "thing.txt"));
        EXPECT_TRUE(contains(vct::assetSearchPathDescription(), dir.string()));
        EXPECT_FALSE(vct::findAsset("sub/other.txt").has_value());
        EXPECT_FALSE(vct::findAsset("sub").has_value()) << "folders are not assets";
    }
    EXPECT_FALSE(vct::findAsset("sub/thing.txt").has_value());
    const std::string description = vct::assetSearchPathDescription();
    EXPECT_TRUE(contains(description, "VCT_ASSET_DIR")) << description;
    EXPECT_TRUE(contains(description, std::string(VCT_SOURCE_DIR) + "/assets")) << description;
    EXPECT_TRUE(contains(description, "shared/assets")) << description;
}

TEST(Asset, SponzaNotFoundMessage) {
    // Only checkable when no Sponza is reachable; otherwise the message is covered by review.
    if (vct::findAsset("sponza/Sponza.gltf"))
        GTEST_SKIP() << "Sponza is in the asset search path; the not-found message is not "
                        "reachable here";
    const std::string message = errorOf([] { vct::loadScene("sponza"); });
    EXPECT_TRUE(contains(message, "fetch_sponza.sh")) << message;
    EXPECT_TRUE(contains(message, "VCT_ASSET_DIR")) << message;
}

// ------------------------------------------------------------------------------------------------
// Light and camera validation

TEST(Loader, GltfPointLight) {
    // The same file with its spot turned into a KHR_lights_punctual point light.
    std::string gltf = farAwayGltf();
    const std::string spot = R"({"name": "SpotData", "type": "spot", "color": [1, 0.5, 0.5], "intensity": 5,
     "spot": {"innerConeAngle": 0.3, "outerConeAngle": 0.6}})";
    const std::size_t at = gltf.find(spot);
    ASSERT_NE(at, std::string::npos);
    gltf.replace(at, spot.size(), R"({"name": "Bulb", "type": "point", "color": [0.5, 1, 0.25], "intensity": 7})");
    const fs::path dir = vct::test::testDir();
    writeText(dir / "point.gltf", gltf);
    const Scene scene = vct::loadModelFile(dir / "point.gltf");
    ASSERT_EQ(scene.lights.size(), 1u);
    const vct::Light& light = scene.lights[0];
    EXPECT_EQ(light.type, vct::LightType::Point);
    EXPECT_NEAR(light.position.x, 1000000.0, 1e-9);  // its node's origin
    EXPECT_NEAR(light.position.y, 2.0, 1e-9);
    EXPECT_NEAR(light.position.z, 0.0, 1e-9);
    EXPECT_NEAR(light.intensity, 7.0, 1e-6);  // candela taken as W/sr, like a spot's
    EXPECT_NEAR(light.color.x, 0.5, 1e-6);
    EXPECT_NEAR(light.color.y, 1.0, 1e-6);
    EXPECT_NEAR(light.color.z, 0.25, 1e-6);
    EXPECT_NO_THROW(vct::validateLight(light, "the file's point light"));
}

TEST(SceneValidation, Lights) {
    vct::Light sun;
    EXPECT_NO_THROW(vct::validateLight(sun, "sun"));
    EXPECT_NE(vct::describe(sun).find("irradiance 1 W/m²"), std::string::npos)
        << vct::describe(sun);

    auto messageFor = [](vct::Light light) {
        return errorOf([&] { vct::validateLight(light, "the light 'key'"); });
    };
    vct::Light l = sun;
    l.irradiance = 0.0;
    EXPECT_TRUE(contains(messageFor(l), "irradiance")) << messageFor(l);
    EXPECT_TRUE(contains(messageFor(l), "the light 'key'"));
    l = sun;
    l.irradiance = NAN;
    EXPECT_TRUE(contains(messageFor(l), "irradiance"));
    l = sun;
    l.direction = glm::dvec3(0.0);
    EXPECT_TRUE(contains(messageFor(l), "direction"));
    l = sun;
    l.direction.x = INFINITY;
    EXPECT_TRUE(contains(messageFor(l), "direction"));
    l = sun;
    l.color = glm::dvec3(1.0, -1.0, 1.0);
    EXPECT_TRUE(contains(messageFor(l), "colour"));

    vct::Light spot;
    spot.type = vct::LightType::Spot;
    spot.position = {0, 2, 0};
    spot.intensity = 8.0;
    EXPECT_NO_THROW(vct::validateLight(spot, "spot"));
    l = spot;
    l.intensity = -1.0;
    EXPECT_TRUE(contains(messageFor(l), "intensity"));
    l = spot;
    l.innerAngleDeg = 50.0;
    l.outerAngleDeg = 40.0;
    EXPECT_TRUE(contains(messageFor(l), "inner cone angle"));
    l = spot;
    l.outerAngleDeg = 90.0;
    EXPECT_TRUE(contains(messageFor(l), "outer cone angle"));
    l = spot;
    l.position.y = NAN;
    EXPECT_TRUE(contains(messageFor(l), "position"));
    // A spot's irradiance field is irrelevant, a sun's intensity too.
    l = spot;
    l.irradiance = -5.0;
    EXPECT_NO_THROW(vct::validateLight(l, "spot"));

    // A point light shines every way: its direction and cone angles are not used.
    vct::Light point;
    point.type = vct::LightType::Point;
    point.position = {0, 2, 0};
    point.intensity = 3.0;
    point.direction = glm::dvec3(0.0);
    point.outerAngleDeg = 120.0;
    EXPECT_NO_THROW(vct::validateLight(point, "point"));
    EXPECT_NE(vct::describe(point).find("point light"), std::string::npos) << vct::describe(point);
    l = point;
    l.intensity = 0.0;
    EXPECT_TRUE(contains(messageFor(l), "point light")) << messageFor(l);
    EXPECT_TRUE(contains(messageFor(l), "intensity"));
    l = point;
    l.intensity = 1e30;
    EXPECT_TRUE(contains(messageFor(l), "supported range")) << messageFor(l);
    l = point;
    l.position.z = INFINITY;
    EXPECT_TRUE(contains(messageFor(l), "position"));
}

TEST(SceneValidation, Cameras) {
    vct::Camera camera;
    camera.name = "main";
    EXPECT_NO_THROW(vct::validateCamera(camera));
    auto messageFor = [](const vct::Camera& c) {
        return errorOf([&] { vct::validateCamera(c); });
    };
    vct::Camera c = camera;
    c.eye.x = NAN;
    EXPECT_TRUE(contains(messageFor(c), "eye")) << messageFor(c);
    EXPECT_TRUE(contains(messageFor(c), "'main'"));
    c = camera;
    c.target = c.eye;
    EXPECT_TRUE(contains(messageFor(c), "same point")) << messageFor(c);
    c = camera;
    c.up = {0.0, 0.0, 2.0};  // parallel to the view direction (0,0,-1)
    EXPECT_TRUE(contains(messageFor(c), "parallel")) << messageFor(c);
    c = camera;
    c.up = glm::dvec3(0.0);
    EXPECT_TRUE(contains(messageFor(c), "up")) << messageFor(c);
    for (double fov : {0.0, 180.0, -10.0, double(NAN)}) {
        c = camera;
        c.fovYDeg = fov;
        EXPECT_TRUE(contains(messageFor(c), "field of view")) << messageFor(c);
    }
}

// ------------------------------------------------------------------------------------------------
// Sponza

TEST(Loader, Sponza) {
    const auto path = vct::findAsset("sponza/Sponza.gltf");
    if (!path)
        GTEST_SKIP() << "Sponza not found in the asset search path ("
                     << vct::assetSearchPathDescription()
                     << "); run assets/fetch_sponza.sh or set VCT_ASSET_DIR";
    const auto start = std::chrono::steady_clock::now();
    const Scene scene = vct::loadScene("sponza");
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("[ sponza   ] loaded in %.2f s: %zu triangles (%zu in the file, %zu zero-area), "
                "%zu vertices, %zu materials, %zu textures\n",
                seconds, scene.triangleCount(), scene.report.sourceTriangles,
                scene.report.degenerateTriangles, scene.vertices.size(), scene.materials.size(),
                scene.textures.size());

    EXPECT_EQ(scene.name, "sponza");
    EXPECT_EQ(scene.report.sourceTriangles, 262087u);  // 115,580 stored, instanced
    EXPECT_EQ(scene.triangleCount() + scene.report.degenerateTriangles, 262087u);
    EXPECT_LE(scene.report.degenerateTriangles, 50u);
    EXPECT_EQ(scene.report.nonFinitePositions, 0u);
    EXPECT_TRUE(scene.report.missingTextures.empty());

    EXPECT_NEAR(scene.worldBounds.min.x, -26.8448, 1e-3);
    EXPECT_NEAR(scene.worldBounds.min.y, 2.2819, 1e-3);
    EXPECT_NEAR(scene.worldBounds.min.z, -16.4778, 1e-3);
    EXPECT_NEAR(scene.worldBounds.max.x, 24.1774, 1e-3);
    EXPECT_NEAR(scene.worldBounds.max.y, 23.6169, 1e-3);
    EXPECT_NEAR(scene.worldBounds.max.z, 14.8997, 1e-3);
    EXPECT_EQ(scene.origin, scene.worldBounds.centre());

    ASSERT_EQ(scene.cameras.size(), 4u);
    EXPECT_EQ(scene.cameras[0].name, "CameraMain");
    for (const char* name : {"CameraAlternate", "CameraBalcony", "CameraAlcove"})
        EXPECT_NO_THROW(scene.camera(name));
    for (const vct::Camera& camera : scene.cameras) {
        EXPECT_NEAR(camera.fovYDeg, 45.0, 1e-3) << camera.name;
        // Every preset stands inside the building.
        for (int a = 0; a < 3; ++a) {
            EXPECT_GT(camera.eye[a], scene.worldBounds.min[a]) << camera.name;
            EXPECT_LT(camera.eye[a], scene.worldBounds.max[a]) << camera.name;
        }
    }
    // CameraMain stands at the +x end of the nave and looks down it (−x).
    const vct::Camera& main = scene.cameras[0];
    EXPECT_NEAR(main.eye.x, 15.4646, 1e-3);
    EXPECT_NEAR(main.eye.y, 4.3879, 1e-3);
    EXPECT_NEAR(main.eye.z, 0.4524, 1e-3);
    EXPECT_LT(glm::normalize(main.target - main.eye).x, -0.9);

    int masks = 0;
    for (const vct::Material& m : scene.materials)
        if (m.alphaMode == vct::AlphaMode::Mask) ++masks;
    EXPECT_EQ(masks, 3);
    for (const char* name : {"PotPlant1", "Chain", "Plants"})
        EXPECT_EQ(materialNamed(scene, name).alphaMode, vct::AlphaMode::Mask) << name;
    EXPECT_GE(scene.textures.size(), 24u);
    for (const vct::Texture& t : scene.textures) {
        EXPECT_GT(t.width, 0);
        EXPECT_EQ(t.rgba.size(), std::size_t(t.width) * t.height * 4);
    }

    ASSERT_EQ(scene.lights.size(), 1u);
    EXPECT_EQ(scene.lights[0].type, vct::LightType::Directional);
    EXPECT_LT(scene.lights[0].direction.y, -0.9);
    EXPECT_DOUBLE_EQ(scene.lights[0].irradiance, 10.0);
    EXPECT_DOUBLE_EQ(scene.exposureEV, 0.0);
    EXPECT_LT(seconds, 15.0);
}

}  // namespace
