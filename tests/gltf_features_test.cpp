// glTF features that used to be dropped without a word (issue 15): vertex colours, sampler wrap
// modes and KHR_texture_transform must reach every pass that reads a material (G-buffer,
// voxelization, light-view map) and the reference path tracer alike; extensions a file requires
// that vct does not implement are refused, unsupported used ones warned about. Every model is a
// one-quad glTF written here (tests/gltf_quad.hpp), rendered through the real `vct` command.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/error.hpp"
#include "core/image.hpp"
#include "gltf_quad.hpp"
#include "scene/gltf_support.hpp"
#include "scene/scene_loader.hpp"
#include "test_util.hpp"

namespace fs = std::filesystem;
using vct::ImageF;
using vct::test::GltfQuad;

namespace {

constexpr double kPi = 3.14159265358979323846;

// 8×8 texture, four 4×4 quadrants (image rows top to bottom): red | green over blue | white.
// Pure 0/255 values, so their linear colours are exactly 0 and 1.
std::string quadrantPng(const fs::path& dir) {
    vct::Image8 image(8, 8);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            const bool right = x >= 4, bottom = y >= 4;
            std::uint8_t* t = image.at(x, y);
            t[0] = (!bottom && !right) || (bottom && right) ? 255 : 0;
            t[1] = (!bottom && right) || (bottom && right) ? 255 : 0;
            t[2] = bottom ? 255 : 0;
            t[3] = 255;
        }
    const fs::path file = dir / "quadrants.png";
    vct::writePng(file, image);
    std::ifstream in(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

// The linear colour of quadrantPng at glTF texture coordinates (u, v) already wrapped to [0, 1].
glm::dvec3 quadrantColour(double u, double v) {
    const bool right = u >= 0.5, bottom = v >= 0.5;
    if (!bottom) return right ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
    return right ? glm::dvec3(1, 1, 1) : glm::dvec3(0, 0, 1);
}

glm::dvec3 pixel(const ImageF& image, glm::ivec2 p) {
    const float* v = image.at(p.x, p.y);
    return {v[0], v[1], v[2]};
}

std::string text(glm::dvec3 c) {
    return "(" + std::to_string(c.x) + ", " + std::to_string(c.y) + ", " + std::to_string(c.z) + ")";
}

void expectColour(const ImageF& image, glm::ivec2 p, glm::dvec3 expected, double tolerance, const std::string& what) {
    const glm::dvec3 got = pixel(image, p);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(got[c], expected[c], tolerance)
            << what << " at pixel " << p.x << "," << p.y << ": got " << text(got) << ", expected " << text(expected);
}

// The engine's G-buffer albedo (AOV) and the reference's direct radiance (= albedo under the
// quad's sun, tests/gltf_quad.hpp) of `model`.
struct Renders {
    ImageF engineAlbedo;
    ImageF reference;
};

Renders renderBoth(const fs::path& model, const fs::path& dir) {
    Renders r;
    const std::string view = vct::test::kQuadView;
    const auto engine = vct::test::runVct("render -q --scene " + model.string() + " " + view +
                                          " --voxel-levels 5 --aov albedo --hdr-out " + (dir / "albedo.pfm").string() +
                                          " --out " + (dir / "albedo.png").string());
    EXPECT_EQ(engine.exitCode, 0) << engine.output;
    const auto reference = vct::test::runVct("reference -q --scene " + model.string() + " " + view +
                                             " --spp 4 --bounces 0 --out " + (dir / "reference.pfm").string());
    EXPECT_EQ(reference.exitCode, 0) << reference.output;
    if (engine.exitCode == 0) r.engineAlbedo = vct::readHdrImage(dir / "albedo.pfm");
    if (reference.exitCode == 0) r.reference = vct::readHdrImage(dir / "reference.pfm");
    return r;
}

}  // namespace

// COLOR_0 multiplies the base colour (glTF 2.0 §3.9.2): a quad whose left vertices are
// (1, 0.5, 0) and right ones (0, 0.5, 1), base colour 0.8, shows 0.8 × the interpolated colour.
TEST(GltfFeatures, VertexColoursMultiplyTheBaseColourInEngineAndReference) {
    const fs::path dir = vct::test::testDir();
    GltfQuad quad;
    const glm::vec3 left(1.0f, 0.5f, 0.0f), right(0.0f, 0.5f, 1.0f);
    quad.colors = std::vector<glm::vec3>{left, right, right, left};
    quad.material = {{"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.8, 0.8, 1.0}}}}, {"doubleSided", true}};
    const fs::path model = vct::test::writeGltfQuad(dir, "coloured", quad);

    const vct::Scene scene = vct::loadModelFile(model);
    ASSERT_EQ(scene.vertices.size(), 4u);
    for (const vct::Vertex& v : scene.vertices)
        EXPECT_EQ(v.color, v.position.x < 0.0f ? left : right) << "vertex at x = " << v.position.x;

    const Renders r = renderBoth(model, dir);
    ASSERT_FALSE(r.engineAlbedo.rgba.empty());
    ASSERT_FALSE(r.reference.rgba.empty());
    for (double x : {-0.75, 0.0, 0.75}) {
        const glm::ivec2 p = vct::test::quadPixel(x, 0.1);
        // The pixel centre's x, not the point's: the colour ramps across the pixel.
        const double half = 3.0 * std::tan(0.5 * 45.0 * kPi / 180.0);
        const double centreX = ((p.x + 0.5) / 64.0 * 2.0 - 1.0) * half;
        const double t = 0.5 * (centreX + 1.0);
        const glm::dvec3 expected = 0.8 * glm::mix(glm::dvec3(left), glm::dvec3(right), t);
        // Measured: within 3e-4 (engine) and 6e-4 (reference, 4 samples across the ramp).
        expectColour(r.engineAlbedo, p, expected, 0.003, "engine albedo");
        expectColour(r.reference, p, expected, 0.003, "reference radiance");
    }
}

// The voxels (octree albedo) and the light-view map (photons: the octree's radiance) carry the
// vertex colour too: a quad whose colour runs from red on the left to blue on the right keeps
// that ramp in both views.
TEST(GltfFeatures, VertexColoursReachVoxelsAndPhotons) {
    const fs::path dir = vct::test::testDir();
    GltfQuad quad;
    const glm::vec3 red(1.0f, 0.0f, 0.0f), blue(0.0f, 0.0f, 1.0f);
    quad.colors = std::vector<glm::vec3>{red, blue, blue, red};
    quad.material = {{"doubleSided", true}};
    const fs::path model = vct::test::writeGltfQuad(dir, "coloured", quad);
    for (const char* view : {"voxels", "radiance"}) {
        const fs::path out = dir / (std::string(view) + ".pfm");
        const auto result = vct::test::runVct("render -q --scene " + model.string() + " " + vct::test::kQuadView +
                                              " --voxel-levels 5 --view " + view + " --hdr-out " + out.string() +
                                              " --out " + (dir / "view.png").string());
        ASSERT_EQ(result.exitCode, 0) << result.output;
        const ImageF image = vct::readHdrImage(out);
        // The share of red, r / (r + b), follows the vertex colours' ramp 1 − (x + 1)/2 within
        // 0.03 (measured 0.898, 0.494, 0.102 for the voxels and 0.896, 0.483, 0.104 for the
        // radiance at x = −0.8, 0, 0.8): each voxel averages 1/32 of the quad's width.
        for (double x : {-0.8, 0.0, 0.8}) {
            const glm::dvec3 c = pixel(image, vct::test::quadPixel(x, 0.0));
            ASSERT_GT(c.x + c.z, 0.0) << view << " at x = " << x;
            EXPECT_NEAR(c.x / (c.x + c.z), 1.0 - 0.5 * (x + 1.0), 0.03) << view << " at x = " << x << ": " << text(c);
            EXPECT_LT(c.y, 1e-6 * (c.x + c.z)) << view << ": no green in the vertex colours";
        }
    }
}

// Sampler wrapS/wrapT: the quad's UVs run from −0.5 to 2 on both axes; the 8×8 quadrant texture
// is looked up at u, v ∈ {−0.25, 0.25, 1.25, 1.75}, where the three modes differ.
class GltfWrapModes : public ::testing::TestWithParam<int> {};

TEST_P(GltfWrapModes, SampleOutsideTheUnitSquareAsTheModeSays) {
    const int mode = GetParam();  // GL enum: 10497 repeat, 33071 clamp to edge, 33648 mirrored repeat
    const fs::path dir = vct::test::testDir();
    GltfQuad quad;
    quad.uv0 = {{-0.5f, 2.0f}, {2.0f, 2.0f}, {2.0f, -0.5f}, {-0.5f, -0.5f}};
    quad.png = quadrantPng(dir);
    quad.sampler = {{"wrapS", mode}, {"wrapT", mode}};
    quad.material = {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}, {"doubleSided", true}};
    const fs::path model = vct::test::writeGltfQuad(dir, "wrap", quad);

    const vct::Scene scene = vct::loadModelFile(model);
    const vct::TextureWrap expectedWrap = mode == 33071   ? vct::TextureWrap::ClampToEdge
                                          : mode == 33648 ? vct::TextureWrap::MirroredRepeat
                                                          : vct::TextureWrap::Repeat;
    EXPECT_EQ(scene.materials.at(0).baseColorMapping.wrapS, expectedWrap);
    EXPECT_EQ(scene.materials.at(0).baseColorMapping.wrapT, expectedWrap);

    auto wrap = [&](double c) {
        if (mode == 33071) return std::clamp(c, 0.0, 1.0);
        if (mode == 33648) {
            const double m = c - 2.0 * std::floor(0.5 * c);
            return m < 1.0 ? m : 2.0 - m;
        }
        return c - std::floor(c);
    };
    const Renders r = renderBoth(model, dir);
    ASSERT_FALSE(r.engineAlbedo.rgba.empty());
    ASSERT_FALSE(r.reference.rgba.empty());
    for (double u : {-0.25, 0.25, 1.25, 1.75})
        for (double v : {-0.25, 0.25, 1.25, 1.75}) {
            const glm::ivec2 p = vct::test::quadPixel(-1.0 + 2.0 * (u + 0.5) / 2.5, 1.0 - 2.0 * (v + 0.5) / 2.5);
            const glm::dvec3 expected = quadrantColour(wrap(u), wrap(v));
            const std::string where = " (u, v) = (" + std::to_string(u) + ", " + std::to_string(v) + ")";
            // Measured: exact (0 and 1) in both; the tolerance only allows for rounding.
            expectColour(r.engineAlbedo, p, expected, 0.002, "engine albedo" + where);
            expectColour(r.reference, p, expected, 0.002, "reference radiance" + where);
        }
}

INSTANTIATE_TEST_SUITE_P(Modes, GltfWrapModes, ::testing::Values(10497, 33071, 33648),
                         [](const ::testing::TestParamInfo<int>& info) {
                             return info.param == 10497 ? "Repeat" : info.param == 33071 ? "ClampToEdge" : "MirroredRepeat";
                         });

// KHR_texture_transform with a rotation of 90°, an offset and a texCoord override: TEXCOORD_0 is
// all zeros (it would show red everywhere), TEXCOORD_1 maps the quad to [0, 1]². glTF's matrix
// T·R·S gives (u', v') = (v, 1 − u): the quadrant at glTF (u, v) shows the texture at (v, 1 − u).
TEST(GltfFeatures, TextureTransformRotatesOffsetsAndPicksTheUvSet) {
    const fs::path dir = vct::test::testDir();
    GltfQuad quad;
    quad.uv1 = quad.uv0;
    quad.uv0 = {{0, 0}, {0, 0}, {0, 0}, {0, 0}};
    quad.png = quadrantPng(dir);
    quad.material = {
        {"pbrMetallicRoughness",
         {{"baseColorTexture",
           {{"index", 0},
            {"extensions", {{"KHR_texture_transform", {{"rotation", kPi / 2}, {"offset", {0.0, 1.0}}, {"texCoord", 1}}}}}}}}},
        {"doubleSided", true}};
    quad.top = {{"extensionsUsed", {"KHR_texture_transform"}}};
    const fs::path model = vct::test::writeGltfQuad(dir, "transformed", quad);

    const vct::Scene scene = vct::loadModelFile(model);
    const vct::TextureMapping& mapping = scene.materials.at(0).baseColorMapping;
    EXPECT_EQ(mapping.texCoord, 1);
    // In vct's convention (v up): glTF (u, v) = (0.25, 0.25) is vct (0.25, 0.75) and must land on
    // glTF (0.25, 0.75), vct (0.25, 0.25).
    const glm::vec2 mapped = mapping.apply({9.0f, 9.0f}, {0.25f, 0.75f});
    EXPECT_NEAR(mapped.x, 0.25f, 1e-6f);
    EXPECT_NEAR(mapped.y, 0.25f, 1e-6f);

    const Renders r = renderBoth(model, dir);
    ASSERT_FALSE(r.engineAlbedo.rgba.empty());
    ASSERT_FALSE(r.reference.rgba.empty());
    for (double u : {0.25, 0.75})
        for (double v : {0.25, 0.75}) {
            const glm::ivec2 p = vct::test::quadPixel(2.0 * u - 1.0, 1.0 - 2.0 * v);
            const glm::dvec3 expected = quadrantColour(v, 1.0 - u);
            const std::string where = " (u, v) = (" + std::to_string(u) + ", " + std::to_string(v) + ")";
            // Measured: exact (0 and 1) in both; the tolerance only allows for rounding.
            expectColour(r.engineAlbedo, p, expected, 0.002, "engine albedo" + where);
            expectColour(r.reference, p, expected, 0.002, "reference radiance" + where);
        }
}

// A transform whose scale reaches float's limit: the transformed coordinates overflow in the
// sampler (1236 non-finite pixels on llvmpipe before it was refused). Ignored with a warning,
// like a non-finite one; the image renders finite.
TEST(GltfFeatures, TextureTransformBeyondUsableCoordinatesIsIgnored) {
    const fs::path dir = vct::test::testDir();
    GltfQuad quad;
    quad.png = quadrantPng(dir);
    quad.material = {
        {"pbrMetallicRoughness",
         {{"baseColorTexture", {{"index", 0}, {"extensions", {{"KHR_texture_transform", {{"scale", {3e38, 3e38}}}}}}}}}},
        {"doubleSided", true}};
    quad.top = {{"extensionsUsed", {"KHR_texture_transform"}}};
    const fs::path model = vct::test::writeGltfQuad(dir, "huge_scale", quad);
    EXPECT_EQ(vct::loadModelFile(model).materials.at(0).baseColorMapping.transform, glm::mat3(1.0f));
    const fs::path out = dir / "huge_scale.png";
    const auto result =
        vct::test::runVct("render --scene " + model.string() + " --width 64 --height 48 --voxel-levels 5 --out " + out.string());
    EXPECT_EQ(result.exitCode, 0) << result.output;
    EXPECT_NE(result.output.find("KHR_texture_transform has a non-finite value or an offset or scale beyond ±2^24; ignored"),
              std::string::npos)
        << result.output;
    EXPECT_TRUE(fs::exists(out));
}

namespace {

// The same JSON as a GLB (the JSON chunk alone: the quad's buffer stays a data URI).
fs::path asGlb(const fs::path& gltf) {
    std::ifstream in(gltf, std::ios::binary);
    std::string json((std::istreambuf_iterator<char>(in)), {});
    while (json.size() % 4) json += ' ';
    std::string glb;
    auto u32 = [&](std::uint32_t v) { glb.append(reinterpret_cast<const char*>(&v), 4); };
    u32(0x46546C67u), u32(2), u32(std::uint32_t(12 + 8 + json.size()));
    u32(std::uint32_t(json.size())), u32(0x4E4F534Au);
    glb += json;
    fs::path path = gltf;
    path.replace_extension(".glb");
    std::ofstream(path, std::ios::binary) << glb;
    return path;
}

}  // namespace

// extensionsRequired with an extension vct does not implement: refused, named, no image; in a
// .gltf and in a .glb alike.
TEST(GltfFeatures, RequiredUnknownExtensionIsRefused) {
    const fs::path dir = vct::test::testDir();
    GltfQuad quad;
    quad.top = {{"extensionsUsed", {"KHR_texture_basisu", "KHR_lights_punctual"}},
                {"extensionsRequired", {"KHR_texture_basisu", "KHR_lights_punctual"}}};
    const fs::path gltf = vct::test::writeGltfQuad(dir, "basisu", quad);
    for (const fs::path& model : {gltf, asGlb(gltf)}) {
        const fs::path out = dir / "out.png";
        const auto result = vct::test::runVct("render --scene " + model.string() + " --out " + out.string());
        EXPECT_EQ(result.exitCode, 1) << result.output;
        // Only the unsupported one is named as missing (KHR_lights_punctual is supported).
        EXPECT_NE(result.output.find("cannot read model '" + model.string() +
                                     "': it requires the glTF extension KHR_texture_basisu, which vct does not "
                                     "implement"),
                  std::string::npos)
            << result.output;
        EXPECT_FALSE(fs::exists(out)) << model;
    }
}

// extensionsUsed with an extension vct does not implement: one warning naming it, still loads.
TEST(GltfFeatures, UsedUnknownExtensionIsWarnedOnce) {
    const fs::path dir = vct::test::testDir();
    GltfQuad quad;
    quad.material = {{"doubleSided", true},
                     {"extensions", {{"KHR_materials_clearcoat", {{"clearcoatFactor", 1.0}}}}}};
    quad.top = {{"extensionsUsed", {"KHR_materials_clearcoat", "KHR_texture_transform"}}};
    const fs::path model = vct::test::writeGltfQuad(dir, "clearcoat", quad);
    const auto result = vct::test::runVct("info --scene " + model.string());
    EXPECT_EQ(result.exitCode, 0) << result.output;
    const std::string warning = "warning: " + model.string() +
                                ": uses the glTF extension KHR_materials_clearcoat, which vct does not implement";
    const std::size_t first = result.output.find(warning);
    EXPECT_NE(first, std::string::npos) << result.output;
    EXPECT_EQ(result.output.find(warning, first + 1), std::string::npos) << "warned more than once: " << result.output;
    EXPECT_NE(result.output.find("not supported: uses the glTF extension KHR_materials_clearcoat"), std::string::npos)
        << "the load report lists it: " << result.output;
    EXPECT_EQ(result.output.find("single-sided"), std::string::npos) << result.output;
}

// Skins, morph targets, animations, BLEND and single-sided materials are named in the load report,
// one line each (the JSON alone decides; Assimp is not involved).
TEST(GltfFeatures, DroppedFeaturesAreReported) {
    const nlohmann::json gltf = {
        {"skins", {{{"joints", {0}}}}},
        {"animations", {nlohmann::json::object(), nlohmann::json::object()}},
        {"meshes", {{{"primitives", {{{"targets", {{{"POSITION", 1}}}}}, nlohmann::json::object()}}}}},
        {"materials", {{{"doubleSided", true}, {"alphaMode", "BLEND"}, {"name", "glass"}},
                       nlohmann::json::object(),
                       {{"doubleSided", false}, {"alphaMode", "BLEND"}}}}};
    vct::LoadReport report;
    vct::reportUnsupportedGltfFeatures(gltf, "model.gltf", report);
    const std::vector<std::string> expected = {
        "1 skin: skinned meshes are drawn at their rest pose",
        "1 primitive with morph targets: drawn without them (base shape)",
        "2 animations: not played (static scene)",
        "2 materials with alphaMode BLEND ('glass', 'material 2'): drawn as MASK with cutoff 0.5 (no blending in the "
        "voxel pipeline)",
        "2 of 3 materials single-sided (doubleSided false): drawn two-sided, like every vct surface"};
    EXPECT_EQ(report.unsupportedFeatures, expected);
}

// A missing external buffer is a glTF file with a missing part, not an unknown format.
TEST(GltfFeatures, MissingBufferNamesTheFile) {
    const fs::path dir = vct::test::testDir();
    const fs::path model = vct::test::writeGltfQuad(dir, "split", GltfQuad{});
    nlohmann::json gltf = nlohmann::json::parse(std::ifstream(model));
    gltf["buffers"][0]["uri"] = "split.bin";
    std::ofstream(model) << gltf.dump();
    std::string message;
    try {
        vct::loadModelFile(model);
    } catch (const vct::Error& e) {
        message = e.what();
    }
    EXPECT_NE(message.find("buffer 0 refers to 'split.bin', which was not found (looked for '" +
                           (dir / "split.bin").string() + "')"),
              std::string::npos)
        << message;
    EXPECT_EQ(message.find("is expected"), std::string::npos) << message;
}

// KHR_materials_emissive_strength (which Assimp 5.2 does not read) multiplies the emissive
// colour: W/(m²·sr) = emissiveFactor × emissiveStrength.
TEST(GltfFeatures, EmissiveStrengthMultipliesTheEmissiveColour) {
    const fs::path dir = vct::test::testDir();
    GltfQuad quad;
    quad.material = {{"emissiveFactor", {1.0, 0.5, 0.25}},
                     {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 4.0}}}}},
                     {"doubleSided", true}};
    quad.top = {{"extensionsUsed", {"KHR_materials_emissive_strength"}}};
    const vct::Scene scene = vct::loadModelFile(vct::test::writeGltfQuad(dir, "glowing", quad));
    EXPECT_EQ(scene.materials.at(0).emissive, glm::vec3(4.0f, 2.0f, 1.0f));
    EXPECT_TRUE(scene.report.unsupportedFeatures.empty());

    // A strength whose product overflows float is as bright as vct goes (1e9 W/(m²·sr)), not dark.
    quad.material["extensions"]["KHR_materials_emissive_strength"]["emissiveStrength"] = 1e40;
    const vct::Scene blinding = vct::loadModelFile(vct::test::writeGltfQuad(dir, "blinding", quad));
    EXPECT_EQ(blinding.materials.at(0).emissive, glm::vec3(1e9f));
}
