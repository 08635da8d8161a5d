// Stress 3, non-finite input (docs/robustness.md, policy "Non-finite input"): NaN/Inf (and
// values beyond float's reach) in positions, normals and UVs (glTF with a base64 buffer: OBJ
// parsers read "nan" texture coordinates as 0), in light and camera parameters, on the command
// line and through the API. Each is refused with a message naming it, or sanitised and counted;
// none reaches an image.
#include <cmath>
#include <cstdio>
#include <fstream>

#include "core/error.hpp"
#include "scene/scene_loader.hpp"
#include "stress_util.hpp"
#include "svo_readback.hpp"
#include "test_util.hpp"

using namespace vct;
using namespace vct::test;
namespace fs = std::filesystem;

namespace {

std::string base64(const std::string& bytes) {
    static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
        unsigned v = 0;
        for (std::size_t k = 0; k < 3; ++k) v = (v << 8) | (k < n ? std::uint8_t(bytes[i + k]) : 0u);
        for (std::size_t k = 0; k < 4; ++k) out += k <= n ? table[(v >> (18 - 6 * k)) & 63] : '=';
    }
    return out;
}

template <class T>
void append(std::string& buffer, std::initializer_list<T> values) {
    for (T v : values) buffer.append(reinterpret_cast<const char*>(&v), sizeof v);
}

// A floor quad (4 good vertices) and three triangles with one bad position each (NaN, −Inf, 1e30
// — finite in float, beyond ±1e18); the floor's normals: one NaN, one Inf, one zero; its UVs: one
// NaN, one Inf. Expected: 3 bad positions, 3 triangles dropped with --sanitize, 3 normals and 2
// UVs repaired.
fs::path writeBrokenGltf(const fs::path& dir) {
    const float inf = INFINITY, nan = NAN;
    std::string buffer;
    // 13 positions: floor 0..3, then three triangles 4..12.
    append<float>(buffer, {-1, 0, -1, 1, 0, -1, 1, 0, 1, -1, 0, 1,  //
                           0, 0.5f, 0, nan, 0.5f, 0, 0, 0.5f, 0.5f,  //
                           0, 0.6f, 0, 0.5f, 0.6f, 0, 0, -inf, 0.5f,  //
                           0, 0.7f, 0, 1e30f, 0.7f, 0, 0, 0.7f, 0.5f});
    append<float>(buffer, {nan, 1, 0, 0, inf, 0, 0, 0, 0, 0, 1, 0,  //
                           0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0});
    append<float>(buffer, {0, 0, nan, 0, 1, 1, 0, inf, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0});
    append<std::uint16_t>(buffer, {0, 2, 1, 0, 3, 2, 4, 5, 6, 7, 8, 9, 10, 11, 12});
    const std::size_t indexBytes = 15 * 2;
    std::ofstream(dir / "broken.gltf") << R"({
  "asset": {"version": "2.0"},
  "scenes": [{"nodes": [0]}], "scene": 0,
  "nodes": [{"mesh": 0}],
  "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.8, 0.8, 1]}}],
  "meshes": [{"name": "broken", "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2},
                                                "indices": 3, "material": 0}]}],
  "buffers": [{"byteLength": )" << buffer.size()
                                  << R"(, "uri": "data:application/octet-stream;base64,)" << base64(buffer) << R"("}],
  "bufferViews": [{"buffer": 0, "byteLength": 312}, {"buffer": 0, "byteOffset": 312, "byteLength": 104},
                  {"buffer": 0, "byteOffset": 416, "byteLength": )"
                                  << indexBytes << R"(}],
  "accessors": [
    {"bufferView": 0, "componentType": 5126, "count": 13, "type": "VEC3", "min": [-1, -1, -1], "max": [1, 1, 1]},
    {"bufferView": 0, "byteOffset": 156, "componentType": 5126, "count": 13, "type": "VEC3"},
    {"bufferView": 1, "componentType": 5126, "count": 13, "type": "VEC2"},
    {"bufferView": 2, "componentType": 5123, "count": 15, "type": "SCALAR"}]
})";
    return dir / "broken.gltf";
}

const std::string kSmall = " --width 32 --height 24 --voxel-levels 5 --light-view-res 256 ";

void expectRefused(const std::string& options, const std::string& mentions, const fs::path& dir) {
    const fs::path out = dir / "refused.png";
    fs::remove(out);
    const CommandResult r = runVct("render -q --scene cornell" + kSmall + options + " --out " + out.string());
    EXPECT_EQ(r.exitCode, 1) << options << "\n" << r.output;
    EXPECT_NE(r.output.find("vct: error: "), std::string::npos) << options << "\n" << r.output;
    EXPECT_NE(r.output.find(mentions), std::string::npos) << options << ": expected '" << mentions << "' in\n" << r.output;
    EXPECT_EQ(r.output.find("engine bug"), std::string::npos) << options << "\n" << r.output;
    EXPECT_FALSE(fs::exists(out)) << options << ": an image was written";
}

}  // namespace

TEST(StressNonFinite, GltfPositionsNormalsAndUvsAreRefusedOrSanitised) {
    const auto dir = testDir();
    const fs::path model = writeBrokenGltf(dir);
    // Default: refused, with the count and the first bad vertex.
    const CommandResult refused = runVct("render -q --scene " + model.string() + kSmall + "--out " + (dir / "a.png").string());
    EXPECT_EQ(refused.exitCode, 1) << refused.output;
    EXPECT_NE(refused.output.find("3 vertices have non-finite"), std::string::npos) << refused.output;
    EXPECT_NE(refused.output.find("--sanitize"), std::string::npos) << refused.output;
    EXPECT_FALSE(fs::exists(dir / "a.png"));

    // --sanitize: the three triangles dropped, normals and UVs repaired, every count reported.
    LoadOptions options;
    options.sanitize = true;
    const Scene scene = loadModelFile(model, options);
    EXPECT_EQ(scene.report.nonFinitePositions, 3u);
    EXPECT_EQ(scene.report.droppedTriangles, 3u);
    EXPECT_EQ(scene.report.repairedNormals, 3u);
    EXPECT_EQ(scene.report.repairedUvs, 2u);
    EXPECT_EQ(scene.triangleCount(), 2u);
    const CommandResult r = runVct("render --sanitize --scene " + model.string() + kSmall +
                                   "--eye 0,2,2 --target 0,0,0 --sun-dir 0.2,-1,0.1 --sun-irradiance 3 --out " +
                                   (dir / "b.png").string() + " --hdr-out " + (dir / "b.pfm").string(),
                                   "VCT_LOG=info");  // repaired normals are an info line, the rest warnings
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* said : {"dropped 3 triangles", "rebuilt 3", "set 2 non-finite texture coordinates"})
        EXPECT_NE(r.output.find(said), std::string::npos) << said << " in\n" << r.output;
    const ImageF image = readHdrImage(dir / "b.pfm");
    EXPECT_EQ(countNonFinite(image.rgba), 0u);
    EXPECT_GT(meanRgb(image), 0.01);

    // In-process: every voxel value and pixel of the sanitised model finite.
    Scene lit = scene;
    Light sun;
    sun.direction = glm::normalize(glm::dvec3(0.2, -1.0, 0.1));
    sun.irradiance = 3.0;
    lit.lights = {sun};
    auto context = gl::createContext(gl::defaultBackend());
    Renderer renderer(lit, smallSettings(32, 24, 5, 256));
    Camera camera;
    camera.eye = {0, 2, 2};
    camera.target = {0, 0, 0};
    renderer.renderFrame(camera);
    EXPECT_EQ(countNonFinite(renderer.readHdr().rgba), 0u);
    const Octree& octree = renderer.octree()->octree();
    std::vector<float> values;
    for (const glm::vec4& v : readBuffer<glm::vec4>(renderer.radiance()->cellRadiance, octree.cellCount()))
        values.insert(values.end(), {v.x, v.y, v.z, v.w});
    for (float a : readBuffer<float>(octree.cellArea, octree.cellCount())) values.push_back(a);
    EXPECT_EQ(countNonFinite(values), 0u) << "voxel radiance and areas";
    std::printf("[ nonfinite] glTF: 3 bad positions (NaN, -Inf, 1e30) refused / dropped, 3 normals and 2 UVs repaired; "
                "image and %u voxels finite\n",
                octree.cellCount());
}

TEST(StressNonFinite, LightAndCameraValuesOnTheCommandLineAreRefused) {
    const auto dir = testDir();
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"--spot-intensity nan", "intensity"},       {"--spot-intensity inf", "intensity"},
        {"--spot-intensity -inf", "intensity"},      {"--spot-intensity 1e300", "outside the supported range"},
        {"--spot-intensity 1e-300", "outside the supported range"},
        {"--sun-irradiance nan", "irradiance"},      {"--sun-irradiance inf", "irradiance"},
        {"--sun-irradiance 1e21", "outside the supported range"},
        {"--sun-dir nan,-1,0", "direction"},         {"--sun-dir 0,-inf,0", "direction"},
        {"--sun-dir 0,0,0", "zero vector"},          {"--spot-pos nan,1,0", "position"},
        {"--spot-pos 0,1e19,0", "beyond"},           {"--spot-dir 0,nan,0", "direction"},
        {"--spot-angles nan,20", "cone angles"},     {"--spot-angles 10,inf", "cone angles"},
        {"--spot-angles 0,1e-300", "outer cone angle"},
        {"--samples 0", "--samples"},                {"--samples 100000", "--samples"},
        {"--bounces 0", "--bounces"},                {"--bounces 9", "--bounces"},
        {"--point-intensity nan", "intensity"},      {"--point-intensity 1e300", "outside the supported range"},
        {"--point-pos 0,nan,0", "position"},         {"--point-pos 1e19,0,0", "beyond"},
        {"--sun-irradiance 2 --light-color 1,nan,1", "colour"},
        {"--sun-irradiance 2 --light-color 1e300,1,1", "outside the supported range"},
        {"--light-color 1,1,1", "--light-color"},    {"--eye nan,1,2", "eye"},
        {"--eye 0,inf,2", "eye"},                    {"--eye 0,1,1e19", "beyond"},
        {"--target 0,nan,0", "target"},              {"--up 0,inf,0", "up vector"},
        {"--up 0,0,0", "up vector"},                 {"--fov nan", "field of view"},
        {"--fov inf", "field of view"},              {"--fov 0", "field of view"},
        {"--fov 180", "field of view"},              {"--fov 1e-300", "field of view"},
        {"--exposure nan", "--exposure"},            {"--exposure inf", "--exposure"},
        {"--exposure 1e10", "--exposure"},           {"--gi-scale nan", "--gi-scale"},
        {"--gi-scale inf", "--gi-scale"},            {"--cone-aperture nan", "--cone-aperture"},
        {"--cone-step inf", "--cone-step"},          {"--cone-offset nan", "--cone-offset"},
        {"--cone-lift nan", "--cone-lift"},          {"--cone-lift inf", "--cone-lift"},
        {"--cone-reuse nan", "--cone-reuse"},        {"--cone-reuse -1", "--cone-reuse"},
        {"--cone-carry nan", "--cone-carry"},        {"--cone-carry -1", "--cone-carry"},
        {"--cone-max-distance nan", "--cone-max-distance"}, {"--cone-max-distance -1", "--cone-max-distance"},
        {"--near-field yes", "--near-field"},
        {"--camera-step nan", "--camera-step"},      {"--camera-step 0", "--camera-step"},
    };
    for (const auto& [options, mentions] : cases) expectRefused(options, mentions, dir);
    std::printf("[ nonfinite] %zu non-finite or out-of-range light, camera and display values on the command line: "
                "all refused, no image written\n",
                cases.size());
}

TEST(StressNonFinite, LightCameraAndSceneValuesThroughTheApiAreRefused) {
    Scene scene = makeCornellBox();
    auto context = gl::createContext(gl::defaultBackend());
    Renderer renderer(scene, smallSettings(32, 24, 5, 256));
    renderer.renderFrame(scene.cameras[0]);
    const ImageF good = renderer.readHdr();

    int refused = 0;
    auto expectError = [&](const std::string& what, auto&& call) {
        try {
            call();
            ADD_FAILURE() << what << ": accepted";
        } catch (const Error& e) {
            ++refused;
        }
    };
    const double nan = NAN, inf = INFINITY;
    for (double bad : {nan, inf, -inf, 1e300, 1e-300, 0.0, -1.0}) {
        std::vector<Light> lights = scene.lights;
        lights[0].intensity = bad;
        expectError("intensity", [&] { renderer.setLights(lights); });
    }
    for (double bad : {nan, inf, 1e19, -1e300}) {
        std::vector<Light> lights = scene.lights;
        lights[0].position.y = bad;
        expectError("position", [&] { renderer.setLights(lights); });
        Camera camera = scene.cameras[0];
        camera.eye.z = bad;
        expectError("eye", [&] { renderer.renderFrame(camera); });
        camera = scene.cameras[0];
        camera.target.x = bad;
        expectError("target", [&] { renderer.renderFrame(camera); });
    }
    for (double bad : {nan, inf, -inf}) {
        std::vector<Light> lights = scene.lights;
        lights[0].direction.x = bad;
        expectError("direction", [&] { renderer.setLights(lights); });
        lights = scene.lights;
        lights[0].color.y = bad;
        expectError("colour", [&] { renderer.setLights(lights); });
        Camera camera = scene.cameras[0];
        camera.up.y = bad;
        expectError("up", [&] { renderer.renderFrame(camera); });
        Material material = scene.materials[0];
        material.emissive.y = float(bad);
        expectError("material emission", [&] { renderer.setMaterial(0, material); });
        material = scene.materials[0];
        material.baseColor.x = float(bad);
        expectError("material colour", [&] { renderer.setMaterial(0, material); });
    }
    for (double bad : {nan, inf, 0.0, 180.0, 1e-300}) {
        Camera camera = scene.cameras[0];
        camera.fovYDeg = bad;
        expectError("fov", [&] { renderer.renderFrame(camera); });
    }
    for (double bad : {nan, inf, 100.0}) {
        RenderSettings settings = renderer.settings();
        settings.display.exposureEV = bad;
        expectError("exposure", [&] {  // refused when a renderer takes the settings
            Renderer r(scene, settings);
            r.renderFrame(scene.cameras[0]);
        });
    }
    // A scene whose own light is broken (lights are validated where they are rendered).
    {
        Scene broken = scene;
        broken.lights[0].intensity = NAN;
        expectError("scene light", [&] {
            Renderer r(broken, smallSettings(32, 24, 5, 256));
            r.renderFrame(broken.cameras[0]);
        });
    }
    // A hand-built scene with a NaN vertex (the loaders never produce one).
    {
        Scene broken = scene;
        broken.vertices[3].position.x = NAN;
        expectError("scene vertex", [&] { Renderer r(broken, smallSettings(32, 24, 5, 256)); });
        broken = scene;
        broken.vertices[5].normal.y = INFINITY;
        expectError("scene normal", [&] { Renderer r(broken, smallSettings(32, 24, 5, 256)); });
    }
    // After all that, the renderer still renders the same image (nothing half-applied).
    renderer.setSettings(smallSettings(32, 24, 5, 256));
    renderer.setLights(scene.lights);
    renderer.renderFrame(scene.cameras[0]);
    const ImageF again = renderer.readHdr();
    EXPECT_EQ(countNonFinite(again.rgba), 0u);
    EXPECT_TRUE(again.rgba == good.rgba) << "the renderer must be unchanged by refused input";
    std::printf("[ nonfinite] %d non-finite or out-of-range values through the API refused; the renderer unchanged\n",
                refused);
}
