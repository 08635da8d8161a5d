#pragma once
// A one-quad glTF model written by tests, everything embedded (buffers and the PNG texture as data
// URIs), and the camera and light that make its rendered colour easy to predict:
//   * the quad spans x, y ∈ [−1, 1] at z = 0, facing +z; corners (−1,−1), (1,−1), (1,1), (−1,1);
//   * kQuadView looks at it straight on from z = 3 (a 64×64 image, fov 45°: the quad fills the
//     middle 80 %), so a world point (x, y) is at pixel quadPixel(x, y);
//   * a sun along −z with E = π W/m² makes the direct radiance L = ρ/π · E · cos 0 = ρ, so a
//     reference rendered with --bounces 0 shows the albedo itself.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

namespace vct::test {

struct GltfQuad {
    std::vector<glm::vec2> uv0 = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};  // glTF convention: v down
    std::optional<std::vector<glm::vec2>> uv1;
    std::optional<std::vector<glm::vec3>> colors;                   // COLOR_0, linear RGB
    nlohmann::json material = nlohmann::json::object();
    std::string png;                        // base-colour texture (file bytes), none when empty
    nlohmann::json sampler = nlohmann::json::object();
    nlohmann::json top = nlohmann::json::object();  // merged into the top level (extensions, …)
};

inline std::string base64Of(const std::string& bytes) {
    static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        unsigned n = std::uint8_t(bytes[i]) << 16;
        if (i + 1 < bytes.size()) n |= std::uint8_t(bytes[i + 1]) << 8;
        if (i + 2 < bytes.size()) n |= std::uint8_t(bytes[i + 2]);
        out += table[n >> 18];
        out += table[(n >> 12) & 63];
        out += i + 1 < bytes.size() ? table[(n >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? table[n & 63] : '=';
    }
    return out;
}

inline std::filesystem::path writeGltfQuad(const std::filesystem::path& dir, const std::string& name,
                                           const GltfQuad& quad) {
    std::string buffer;
    auto floats = [&](std::initializer_list<float> values) {
        for (float v : values) buffer.append(reinterpret_cast<const char*>(&v), sizeof v);
    };
    nlohmann::json accessors = nlohmann::json::array(), views = nlohmann::json::array();
    auto accessor = [&](const char* type, int count, std::size_t start, nlohmann::json extra = {}) {
        views.push_back({{"buffer", 0}, {"byteOffset", start}, {"byteLength", buffer.size() - start}});
        nlohmann::json a = {{"bufferView", views.size() - 1}, {"componentType", 5126}, {"count", count}, {"type", type}};
        if (!extra.is_null()) a.update(extra);
        accessors.push_back(a);
        return int(accessors.size() - 1);
    };
    std::size_t start = buffer.size();
    floats({-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0});
    nlohmann::json attributes;
    attributes["POSITION"] = accessor("VEC3", 4, start, {{"min", {-1, -1, 0}}, {"max", {1, 1, 0}}});
    start = buffer.size();
    for (int i = 0; i < 4; ++i) floats({0, 0, 1});
    attributes["NORMAL"] = accessor("VEC3", 4, start);
    start = buffer.size();
    for (const glm::vec2& t : quad.uv0) floats({t.x, t.y});
    attributes["TEXCOORD_0"] = accessor("VEC2", 4, start);
    if (quad.uv1) {
        start = buffer.size();
        for (const glm::vec2& t : *quad.uv1) floats({t.x, t.y});
        attributes["TEXCOORD_1"] = accessor("VEC2", 4, start);
    }
    if (quad.colors) {
        start = buffer.size();
        for (const glm::vec3& c : *quad.colors) floats({c.x, c.y, c.z});
        attributes["COLOR_0"] = accessor("VEC3", 4, start);
    }
    start = buffer.size();
    for (std::uint16_t i : {0, 1, 2, 0, 2, 3}) buffer.append(reinterpret_cast<const char*>(&i), 2);
    views.push_back({{"buffer", 0}, {"byteOffset", start}, {"byteLength", 12}});
    accessors.push_back({{"bufferView", views.size() - 1}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}});
    const int indices = int(accessors.size() - 1);

    nlohmann::json gltf = {
        {"asset", {{"version", "2.0"}}},
        {"scene", 0},
        {"scenes", {{{"nodes", {0}}}}},
        {"nodes", {{{"mesh", 0}}}},
        {"meshes", {{{"primitives", {{{"attributes", attributes}, {"indices", indices}, {"material", 0}}}}}}},
        {"materials", {quad.material}},
        {"buffers", {{{"byteLength", buffer.size()},
                      {"uri", "data:application/octet-stream;base64," + base64Of(buffer)}}}},
        {"bufferViews", views},
        {"accessors", accessors}};
    if (!quad.png.empty()) {
        gltf["images"] = {{{"uri", "data:image/png;base64," + base64Of(quad.png)}}};
        gltf["samplers"] = {quad.sampler};
        gltf["textures"] = {{{"source", 0}, {"sampler", 0}}};
    }
    gltf.update(quad.top);
    const std::filesystem::path path = dir / (name + ".gltf");
    std::ofstream(path) << gltf.dump(1);
    return path;
}

// Camera and sun of the quad scenes (see above), as vct options.
inline const char* kQuadView =
    "--eye 0,0,3 --target 0,0,0 --up 0,1,0 --fov 45 --width 64 --height 64 --sun-dir 0,0,-1 "
    "--sun-irradiance 3.14159265";

// The pixel that sees world point (x, y, 0) through kQuadView.
inline glm::ivec2 quadPixel(double x, double y) {
    const double half = 3.0 * std::tan(0.5 * 45.0 * 3.14159265358979 / 180.0);
    return {int((x / half * 0.5 + 0.5) * 64), int((0.5 - y / half * 0.5) * 64)};
}

}  // namespace vct::test
