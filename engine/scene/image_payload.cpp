#include "scene/image_payload.hpp"

#include <cctype>
#include <cstring>

#include "core/error.hpp"

namespace vct {
namespace {

std::uint32_t le16(const std::uint8_t* p) { return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8; }
std::uint32_t le32(const std::uint8_t* p) { return le16(p) | le16(p + 2) << 16; }

// Bytes an uncompressed image needs after its header, or nothing when it is not one of the
// uncompressed formats this knows (or is compressed).
struct Layout {
    std::uint64_t headerBytes = 0;   // before the texels (headers, colour map, …)
    std::uint64_t payloadBytes = 0;  // the texels
};

std::optional<Layout> tgaLayout(const std::uint8_t* d, std::size_t size, std::uint64_t w, std::uint64_t h) {
    if (size < 18) return std::nullopt;
    const int type = d[2];
    if (type != 1 && type != 2 && type != 3) return std::nullopt;  // 9, 10, 11: RLE
    const std::uint64_t bitsPerTexel = d[16];
    const std::uint64_t colourMap = d[1] ? le16(d + 5) * ((std::uint64_t(d[7]) + 7) / 8) : 0;
    return Layout{18 + std::uint64_t(d[0]) + colourMap, w * h * ((bitsPerTexel + 7) / 8)};
}

std::optional<Layout> bmpLayout(const std::uint8_t* d, std::size_t size, std::uint64_t w, std::uint64_t h) {
    if (size < 30 || d[0] != 'B' || d[1] != 'M') return std::nullopt;
    const std::uint32_t headerSize = le32(d + 14);
    std::uint64_t bitsPerTexel = 0;
    if (headerSize == 12) {  // OS/2: never compressed
        bitsPerTexel = le16(d + 24);
    } else {
        if (size < 34) return std::nullopt;
        const std::uint32_t compression = le32(d + 30);
        if (compression != 0 && compression != 3) return std::nullopt;  // RLE4, RLE8, JPEG, PNG
        bitsPerTexel = le16(d + 28);
    }
    const std::uint64_t rowBytes = (bitsPerTexel * w + 31) / 32 * 4;
    return Layout{le32(d + 10), rowBytes * h};
}

// Binary PNM: "P5"/"P6", then width, height and maxval as text, one whitespace, the texels.
std::optional<Layout> pnmLayout(const std::uint8_t* d, std::size_t size, std::uint64_t w, std::uint64_t h) {
    if (size < 3 || d[0] != 'P' || (d[1] != '5' && d[1] != '6')) return std::nullopt;
    std::size_t i = 2;
    std::uint64_t numbers[3] = {0, 0, 0};
    for (std::uint64_t& n : numbers) {
        while (i < size && (std::isspace(d[i]) || d[i] == '#')) {
            if (d[i] == '#')
                while (i < size && d[i] != '\n') ++i;
            else
                ++i;
        }
        while (i < size && std::isdigit(d[i]) && n < (std::uint64_t(1) << 40)) n = n * 10 + (d[i++] - '0');
    }
    const std::uint64_t channels = d[1] == '6' ? 3 : 1, bytes = numbers[2] > 255 ? 2 : 1;
    return Layout{i + 1, w * h * channels * bytes};
}

}  // namespace

std::optional<std::string> implausibleImagePayload(const std::uint8_t* data, std::size_t size, int width, int height) {
    const std::uint64_t w = std::uint64_t(width > 0 ? width : 0), h = std::uint64_t(height > 0 ? height : 0);
    std::optional<Layout> layout = tgaLayout(data, size, w, h);
    if (!layout) layout = bmpLayout(data, size, w, h);
    if (!layout) layout = pnmLayout(data, size, w, h);
    if (layout) {
        if (layout->headerBytes + layout->payloadBytes <= size) return std::nullopt;
        return concat("an uncompressed ", width, "x", height, " image needs ", layout->payloadBytes,
                      " bytes of texels, but the file has ", size, " bytes in all: truncated or corrupt");
    }
    const std::uint64_t decoded = w * h * 4;
    if (decoded <= kAlwaysAllowedBytes || decoded <= kMaxExpansion * std::uint64_t(size)) return std::nullopt;
    return concat("a ", width, "x", height, " image (", decoded, " bytes decoded) from ", size,
                  " bytes of file is more than any image format compresses (", kMaxExpansion,
                  ":1); truncated or corrupt");
}

}  // namespace vct
