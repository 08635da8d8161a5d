#include "scene/file_precheck.hpp"

#include <cctype>
#include <cstdint>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "core/error.hpp"
#include "core/file_extension.hpp"

namespace fs = std::filesystem;

namespace vct {
namespace {

// A GLB's header and chunk headers against the file's real size. Assimp allocates a chunk's
// declared length before reading it, so an 84-byte file declaring a 4 GiB chunk would make it
// ask for 4 GiB.
void checkGlbSizes(const fs::path& path) {
    const std::string source = path.string();
    std::ifstream in(path, std::ios::binary);
    std::uint32_t header[3] = {0, 0, 0};
    if (!in.read(reinterpret_cast<char*>(header), sizeof header) || header[0] != 0x46546C67u) return;  // not GLB: Assimp decides
    std::error_code ec;
    const std::uint64_t size = fs::file_size(path, ec);
    if (ec) return;
    if (header[2] > size)
        fail("cannot read model '", source, "': the GLB header declares ", header[2], " bytes but the file has ", size,
             " (truncated or corrupt)");
    std::uint64_t offset = 12;
    std::uint32_t chunk[2];
    while (offset + 8 <= header[2] && in.read(reinterpret_cast<char*>(chunk), sizeof chunk)) {
        if (offset + 8 + std::uint64_t(chunk[0]) > header[2])
            fail("cannot read model '", source, "': a GLB chunk at byte ", offset, " declares ", chunk[0],
                 " bytes, beyond the file's ", header[2], " (truncated or corrupt)");
        offset += 8 + std::uint64_t(chunk[0]);
        in.seekg(std::streamoff(offset));
    }
}

std::string trimmed(const std::string& s) {
    std::size_t b = 0, e = s.size();
    while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
    while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
    return s.substr(b, e - b);
}

// An MTL statement before the first `newmtl` has no material to belong to. Assimp 5.2 ignores
// colours there but writes a texture statement (map_Kd, bump, disp, ...) through a null
// material and crashes (tests/data/bad/obj_mtl_before_newmtl.obj), so any statement there is
// refused.
void checkMtlFile(const fs::path& mtl, const std::string& objSource) {
    std::ifstream in(mtl, std::ios::binary);
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        const std::string statement = trimmed(line);
        if (statement.empty() || statement[0] == '#') continue;
        std::istringstream words(statement);
        std::string keyword;
        words >> keyword;
        if (keyword == "newmtl") return;
        fail("cannot read model '", objSource, "': its material file '", mtl.string(), "' line ", number, " says '",
             keyword, "' before any 'newmtl' (no material to belong to); start the file with 'newmtl NAME'");
    }
}

// Every material library an OBJ file can make Assimp open: each `mtllib` line's remainder as one
// name (what Assimp 5.2 opens), each of its words, and the OBJ's own name with .mtl (Assimp's
// fallback when a library is missing).
void checkObjMaterialLibraries(const fs::path& obj) {
    std::ifstream in(obj, std::ios::binary);
    const fs::path folder = obj.parent_path();
    std::set<fs::path> libraries{fs::path(obj).replace_extension(".mtl")};
    std::string line;
    while (std::getline(in, line)) {
        const std::string statement = trimmed(line);
        if (statement.rfind("mtllib", 0) != 0 || statement.size() < 7 || !std::isspace(static_cast<unsigned char>(statement[6])))
            continue;
        const std::string names = trimmed(statement.substr(6));
        libraries.insert(folder / names);
        std::istringstream words(names);
        for (std::string word; words >> word;) libraries.insert(folder / word);
    }
    for (const fs::path& library : libraries) {
        std::error_code ec;
        if (fs::is_regular_file(library, ec)) checkMtlFile(library, obj.string());
    }
}

}  // namespace

void precheckModelFile(const fs::path& path) {
    checkGlbSizes(path);
    if (lowerExtension(path) == ".obj") checkObjMaterialLibraries(path);
}

}  // namespace vct
