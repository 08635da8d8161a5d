#pragma once
// What an image file declares against what it holds, checked from its header before anything is
// decoded, so that a texture never costs far more than its file: stb_image allocates the declared
// width × height first, so a 19-byte TGA declaring 9265×12576 texels would take 1 GB and seconds,
// and an uncompressed image cut short decodes "successfully" with zeros for the missing part.
//
//   * uncompressed TGA (types 1, 2, 3), BMP (BI_RGB, BI_BITFIELDS) and binary PNM (P5, P6):
//     refused when the declared texels need more bytes than the file has after its header;
//   * everything else (PNG, JPEG, RLE TGA/BMP, GIF, PSD, HDR, PIC): refused when the decoded
//     RGBA8 image would be more than kMaxExpansion times the file (PNG's deflate cannot expand
//     more than 1032:1, times 4 for grey to RGBA; JPEG, RLE and LZW stay well below) and more
//     than kAlwaysAllowedBytes.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace vct {

constexpr std::uint64_t kMaxExpansion = 4200;
constexpr std::uint64_t kAlwaysAllowedBytes = std::uint64_t(1) << 22;  // 4 MiB decoded, 1024² RGBA

// Why the image in `data` (the whole file) cannot hold the `width` × `height` texels its header
// declares (as stbi_info read them), or nothing when it can.
std::optional<std::string> implausibleImagePayload(const std::uint8_t* data, std::size_t size, int width, int height);

}  // namespace vct
