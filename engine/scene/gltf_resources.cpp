#include "scene/gltf_resources.hpp"

#include <cctype>
#include <string>

#include "core/error.hpp"
#include "scene/gltf_json.hpp"

namespace fs = std::filesystem;

namespace vct {
namespace {

std::string percentDecoded(const std::string& s) {
    std::string out;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (s[i] == '%' && i + 2 < s.size() && std::isxdigit(static_cast<unsigned char>(s[i + 1])) &&
            std::isxdigit(static_cast<unsigned char>(s[i + 2]))) {
            out.push_back(static_cast<char>(std::stoi(s.substr(i + 1, 2), nullptr, 16)));
            i += 2;
        } else {
            out.push_back(s[i]);
        }
    }
    return out;
}

bool isFile(const fs::path& p) {
    std::error_code ec;
    return fs::is_regular_file(p, ec);
}

}  // namespace

void checkGltfResources(const nlohmann::json& gltf, const fs::path& modelPath) {
    const fs::path folder = modelPath.parent_path();
    const nlohmann::json& buffers = gltfArray(gltf, "buffers");
    for (std::size_t i = 0; i < buffers.size(); ++i) {
        const nlohmann::json* uri = gltfMember(buffers[i], "uri");
        if (!uri || !uri->is_string()) continue;  // a GLB's own binary chunk
        const std::string text = uri->get<std::string>();
        // data: URIs are embedded; other schemes (http:, file:) are Assimp's to refuse.
        if (text.empty() || text.find(':') != std::string::npos) continue;
        const fs::path asWritten = folder / text, decoded = folder / percentDecoded(text);
        if (isFile(asWritten) || isFile(decoded)) continue;
        fail("cannot read model '", modelPath.string(), "': its buffer ", i, " refers to '", text,
             "', which was not found (looked for '", decoded.lexically_normal().string(),
             "'); put that file beside the model, or export the model as one .glb file");
    }
}

}  // namespace vct
