// libFuzzer target for the scene loader (docs/robustness.md, bad files): every input must end in
// a loaded, sane Scene or a vct::Error — never a crash, a sanitizer report, another exception or
// a Scene with non-finite data. Build and run: docs/robustness.md "Fuzzing the loader".
//
// Input: the first byte picks the format (0: glTF, 1: GLB, 2: OBJ, 3: an image decoded from
// memory); the rest is the file. For OBJ, bytes after a "\n#MTL\n" marker become model.mtl next to
// it (the seeds' OBJ files say "mtllib model.mtl").
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include <unistd.h>

#include "core/error.hpp"
#include "core/log.hpp"
#include "scene/scene_loader.hpp"
#include "scene/texture_decode.hpp"

namespace {

std::filesystem::path workDir() {
    static const std::filesystem::path dir = [] {
        auto d = std::filesystem::temp_directory_path() / ("vct_fuzz_" + std::to_string(getpid()));
        std::filesystem::create_directories(d);
        return d;
    }();
    return dir;
}

void writeFile(const std::filesystem::path& path, std::string_view bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), std::streamsize(bytes.size()));
}

bool finite3(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// What buildSceneGeometry and the material import promise about a Scene they return.
void checkScene(const vct::Scene& scene) {
    bool ok = scene.triangleCount() > 0 && scene.indices.size() % 3 == 0;
    for (const vct::Vertex& v : scene.vertices)
        ok = ok && finite3(v.position) && finite3(v.normal) && std::isfinite(v.uv.x) && std::isfinite(v.uv.y);
    for (std::uint32_t i : scene.indices) ok = ok && i < scene.vertices.size();
    for (const vct::Material& m : scene.materials)
        ok = ok && finite3(m.baseColor) && finite3(m.emissive) && std::isfinite(m.baseAlpha) &&
             (m.baseColorTexture < int(scene.textures.size()));
    for (const vct::Texture& t : scene.textures)
        ok = ok && t.width > 0 && t.height > 0 && t.rgba.size() == std::size_t(t.width) * t.height * 4;
    ok = ok && !scene.cameras.empty() && !scene.lights.empty();
    if (!ok) {
        std::fprintf(stderr, "fuzz_loader: the loader returned an inconsistent scene\n");
        std::abort();
    }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    vct::setLogLevel(vct::LogLevel::Quiet);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 1) return 0;
    const int mode = data[0] % 4;
    const std::string_view body(reinterpret_cast<const char*>(data + 1), size - 1);
    try {
        if (mode == 3) {
            std::string error;
            if (auto texture = vct::decodeImageMemory(data + 1, size - 1, "fuzz", error))
                if (texture->rgba.size() != std::size_t(texture->width) * texture->height * 4) std::abort();
            return 0;
        }
        // Each input starts from an empty folder: a file an earlier input left (a model.mtl that
        // an OBJ-text .glb names) would make a crash depend on the run's history, and its
        // artifact would not reproduce it alone.
        for (const auto& entry : std::filesystem::directory_iterator(workDir())) std::filesystem::remove_all(entry);
        const char* names[] = {"model.gltf", "model.glb", "model.obj"};
        const std::filesystem::path model = workDir() / names[mode];
        std::string_view file = body;
        if (mode == 2) {
            const std::size_t marker = body.find("\n#MTL\n");
            writeFile(workDir() / "model.mtl", marker == std::string_view::npos ? "" : body.substr(marker + 6));
            if (marker != std::string_view::npos) file = body.substr(0, marker + 1);
        }
        writeFile(model, file);
        for (bool sanitize : {false, true}) {
            try {
                checkScene(vct::loadModelFile(model, vct::LoadOptions{sanitize}));
            } catch (const vct::Error&) {
                // A clear error is a correct answer to a bad file.
            }
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fuzz_loader: unexpected exception (not vct::Error): %s\n", e.what());
        std::abort();
    }
    return 0;
}
