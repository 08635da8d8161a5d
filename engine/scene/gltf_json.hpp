#pragma once
// The JSON of a glTF 2.0 model (a .gltf file, or the JSON chunk of a .glb), read by vct itself
// for what Debian 12's Assimp 5.2 does not pass on: the extensions a file requires and uses,
// KHR_texture_transform, KHR_materials_emissive_strength, the buffers and images it refers to,
// and the features vct does not draw (skins, animations, single-sided materials). Assimp still
// reads the geometry; this is only looked at.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace vct {

// The file's JSON, or nothing when `path` is not a glTF/GLB file or its JSON does not parse (Assimp
// then reports what is wrong, as it does for any corrupt file).
std::optional<nlohmann::json> readGltfJson(const std::filesystem::path& path);

// Small safe accessors: a missing member or one of another type gives the fallback, never throws.
const nlohmann::json* gltfMember(const nlohmann::json& object, const char* key);  // null if absent
const nlohmann::json& gltfArray(const nlohmann::json& object, const char* key);    // empty if absent
std::optional<std::size_t> gltfIndex(const nlohmann::json& object, const char* key);  // unsigned integer
double gltfNumber(const nlohmann::json& object, const char* key, double fallback);
std::vector<std::string> gltfStrings(const nlohmann::json& object, const char* key);

}  // namespace vct
