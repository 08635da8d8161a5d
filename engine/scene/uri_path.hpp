#pragma once
// Files that a model names by URI (glTF buffers and images, OBJ/MTL texture paths): the name with
// %XX escapes decoded, and whether a candidate path is an existing regular file (never throws:
// an unreadable folder on the way is simply "not here").
#include <cctype>
#include <filesystem>
#include <string>
#include <system_error>

namespace vct {

inline std::string percentDecoded(const std::string& s) {
    std::string out;
    out.reserve(s.size());
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

inline bool isRegularFile(const std::filesystem::path& p) {
    std::error_code ec;
    return std::filesystem::is_regular_file(p, ec);
}

}  // namespace vct
