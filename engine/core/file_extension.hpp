#pragma once
// A file's extension in lower case (".gltf", ".pfm", ...), for choosing a format by name.
#include <cctype>
#include <filesystem>
#include <string>

namespace vct {

inline std::string lowerExtension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

}  // namespace vct
