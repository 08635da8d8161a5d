#include "scene/gltf_json.hpp"

#include <cstdint>
#include <fstream>
#include <iterator>

#include "core/file_extension.hpp"

namespace fs = std::filesystem;

namespace vct {
namespace {

std::optional<std::string> readText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return std::nullopt;
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// The first chunk of a GLB (its JSON). precheckModelFile has checked the chunk sizes already;
// they are checked again here so that this function is safe on its own.
std::optional<std::string> glbJsonChunk(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::uint32_t header[5] = {};
    if (!in.read(reinterpret_cast<char*>(header), sizeof header)) return std::nullopt;
    if (header[0] != 0x46546C67u || header[4] != 0x4E4F534Au) return std::nullopt;  // "glTF", "JSON"
    std::error_code ec;
    const std::uint64_t size = fs::file_size(path, ec);
    if (ec || 20 + std::uint64_t(header[3]) > size) return std::nullopt;
    std::string text(header[3], '\0');
    if (!in.read(text.data(), std::streamsize(text.size()))) return std::nullopt;
    return text;
}

}  // namespace

std::optional<nlohmann::json> readGltfJson(const fs::path& path) {
    const std::string ext = lowerExtension(path);
    std::optional<std::string> text;
    if (ext == ".gltf") text = readText(path);
    else if (ext == ".glb") text = glbJsonChunk(path);
    if (!text) return std::nullopt;
    nlohmann::json json = nlohmann::json::parse(*text, nullptr, /*allow_exceptions=*/false);
    if (json.is_discarded() || !json.is_object()) return std::nullopt;
    return json;
}

const nlohmann::json* gltfMember(const nlohmann::json& object, const char* key) {
    if (!object.is_object()) return nullptr;
    const auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
}

const nlohmann::json& gltfArray(const nlohmann::json& object, const char* key) {
    static const nlohmann::json empty = nlohmann::json::array();
    const nlohmann::json* member = gltfMember(object, key);
    return member && member->is_array() ? *member : empty;
}

std::optional<std::size_t> gltfIndex(const nlohmann::json& object, const char* key) {
    const nlohmann::json* member = gltfMember(object, key);
    if (!member || !member->is_number_unsigned()) return std::nullopt;
    return member->get<std::size_t>();
}

double gltfNumber(const nlohmann::json& object, const char* key, double fallback) {
    const nlohmann::json* member = gltfMember(object, key);
    return member && member->is_number() ? member->get<double>() : fallback;
}

std::vector<std::string> gltfStrings(const nlohmann::json& object, const char* key) {
    std::vector<std::string> out;
    for (const nlohmann::json& item : gltfArray(object, key))
        if (item.is_string()) out.push_back(item.get<std::string>());
    return out;
}

}  // namespace vct
