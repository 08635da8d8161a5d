#include "scene/gltf_resources.hpp"

#include <string>

#include "core/error.hpp"
#include "scene/gltf_json.hpp"
#include "scene/uri_path.hpp"

namespace fs = std::filesystem;

namespace vct {

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
        if (isRegularFile(asWritten) || isRegularFile(decoded)) continue;
        fail("cannot read model '", modelPath.string(), "': its buffer ", i, " refers to '", text,
             "', which was not found (looked for '", decoded.lexically_normal().string(),
             "'); put that file beside the model, or export the model as one .glb file");
    }
}

}  // namespace vct
