#include "core/image.hpp"

#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>

#include <stb_image.h>
#include <stb_image_write.h>
#include <tinyexr.h>

#include "core/error.hpp"
#include "core/file_extension.hpp"

namespace vct {
namespace fs = std::filesystem;

void validateImageSize(int width, int height, const char* what) {
    if (width < 1 || height < 1 || width > kMaxImageSide || height > kMaxImageSide)
        fail(what, " ", width, "x", height, " is out of range; --width and --height must be within 1..",
             kMaxImageSide);
}

namespace {
void writePfm(const fs::path& path, const ImageF& image) {
    std::ofstream file(path, std::ios::binary);
    if (!file) fail("cannot write '", path.string(), "': check that the folder exists and is writable");
    // Negative scale = little-endian floats; rows run bottom to top.
    file << "PF\n" << image.width << " " << image.height << "\n-1.0\n";
    std::vector<float> row(std::size_t(image.width) * 3);
    for (int y = image.height - 1; y >= 0; --y) {
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < 3; ++c) row[std::size_t(x) * 3 + c] = image.at(x, y)[c];
        file.write(reinterpret_cast<const char*>(row.data()), std::streamsize(row.size() * sizeof(float)));
    }
    if (!file) fail("writing '", path.string(), "' failed (disk full?)");
}

ImageF readPfm(const fs::path& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) fail("cannot open '", path.string(), "'");
    std::string magic;
    int width = 0, height = 0;
    double scale = 0.0;
    file >> magic >> width >> height >> scale;
    file.get();  // the single whitespace byte that ends the header
    const int channels = magic == "PF" ? 3 : magic == "Pf" ? 1 : 0;
    if (!file || channels == 0 || width <= 0 || height <= 0 || width > 65536 || height > 65536 || scale == 0.0)
        fail("'", path.string(), "' is not a valid PFM image (bad header)");
    if (scale > 0.0) fail("'", path.string(), "' is a big-endian PFM; only little-endian PFM is supported");
    ImageF image(width, height);
    std::vector<float> row(std::size_t(width) * channels);
    for (int y = height - 1; y >= 0; --y) {
        file.read(reinterpret_cast<char*>(row.data()), std::streamsize(row.size() * sizeof(float)));
        if (!file) fail("'", path.string(), "' is truncated (expected ", width, "x", height, " pixels)");
        for (int x = 0; x < width; ++x) {
            float* p = image.at(x, y);
            for (int c = 0; c < 3; ++c) p[c] = row[std::size_t(x) * channels + (channels == 3 ? c : 0)];
            p[3] = 1.0f;
        }
    }
    return image;
}
}  // namespace

void ensureWritable(const fs::path& path) {
    const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
    if (!fs::is_directory(folder))
        fail("cannot write '", path.string(), "': folder '", folder.string(), "' does not exist");
}

void ensureWritablePng(const fs::path& path, const char* option) {
    ensureWritable(path);
    if (lowerExtension(path) != ".png")
        fail(option, " writes a PNG image: name the file .png, not '", path.string(), "'");
}

void ensureWritableHdr(const fs::path& path, const char* option) {
    ensureWritable(path);
    const std::string ext = lowerExtension(path);
    if (ext != ".pfm" && ext != ".exr")
        fail(option, " writes linear HDR: name the file .pfm or .exr, not '", path.string(), "'");
}

void writePng(const fs::path& path, const Image8& image) {
    ensureWritable(path);
    if (!stbi_write_png(path.c_str(), image.width, image.height, 4, image.rgba.data(), image.width * 4))
        fail("cannot write PNG '", path.string(), "': check that the folder is writable");
}

Image8 readPng(const fs::path& path) {
    int w = 0, h = 0, n = 0;
    unsigned char* data = stbi_load(path.c_str(), &w, &h, &n, 4);
    if (!data) fail("cannot read image '", path.string(), "': ", stbi_failure_reason());
    Image8 image(w, h);
    std::memcpy(image.rgba.data(), data, image.rgba.size());
    stbi_image_free(data);
    return image;
}

void writeHdrImage(const fs::path& path, const ImageF& image) {
    ensureWritable(path);
    const std::string ext = lowerExtension(path);
    if (ext == ".pfm") return writePfm(path, image);
    if (ext == ".exr") {
        const char* error = nullptr;
        if (SaveEXR(image.rgba.data(), image.width, image.height, 4, /*save_as_fp16=*/0, path.c_str(), &error) !=
            TINYEXR_SUCCESS) {
            std::string message = error ? error : "unknown error";
            FreeEXRErrorMessage(error);
            fail("cannot write OpenEXR '", path.string(), "': ", message);
        }
        return;
    }
    fail("unsupported HDR output '", path.string(), "': use a .pfm or .exr file name");
}

ImageF readHdrImage(const fs::path& path) {
    if (!fs::exists(path)) fail("image '", path.string(), "' not found");
    const std::string ext = lowerExtension(path);
    if (ext == ".pfm") return readPfm(path);
    if (ext == ".exr") {
        float* data = nullptr;
        int w = 0, h = 0;
        const char* error = nullptr;
        if (LoadEXR(&data, &w, &h, path.c_str(), &error) != TINYEXR_SUCCESS) {
            std::string message = error ? error : "unknown error";
            FreeEXRErrorMessage(error);
            fail("cannot read OpenEXR '", path.string(), "': ", message);
        }
        ImageF image(w, h);
        std::memcpy(image.rgba.data(), data, image.rgba.size() * sizeof(float));
        std::free(data);
        return image;
    }
    fail("unsupported HDR image '", path.string(), "': use .pfm or .exr");
}

}  // namespace vct
