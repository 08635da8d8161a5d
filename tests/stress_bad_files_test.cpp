// Stress 8, bad files (docs/robustness.md, policy "Bad files"): the malformed glTF/GLB/OBJ/MTL
// and image files of tests/data/bad (made by its make_corpus.py) through the real `vct` command
// and through loadModelFile in-process. Each ends in one clear error naming the file, or in the
// documented fallback with a warning — never a crash, another exception or a non-finite scene.
// The libFuzzer target for the same loader is tests/fuzz (ctest StressFuzz.Loader1500FixedSeedRuns).
#include <cmath>
#include <cstdio>
#include <fstream>

#include "core/error.hpp"
#include "scene/image_payload.hpp"
#include "scene/scene_loader.hpp"
#include "scene/texture_decode.hpp"
#include "stress_util.hpp"
#include "test_util.hpp"

using namespace vct;
using namespace vct::test;
namespace fs = std::filesystem;

namespace {

const fs::path kBad = fs::path(VCT_TEST_DATA_DIR) / "bad";

struct Expectation {
    std::string file;
    int exitCode;          // 1: a clear error; 0: a documented fallback
    std::string mentions;  // in the error or the warning
};

// Errors name the file; fallbacks warn and load the rest.
const std::vector<Expectation> kModels = {
    {"gltf_truncated.gltf", 1, "cannot read model"},
    {"gltf_not_json.gltf", 1, "cannot read model"},
    {"gltf_empty.gltf", 1, "cannot read model"},
    {"gltf_version_1.gltf", 1, "cannot read model"},
    {"gltf_missing_buffer.gltf", 1, "missing.bin"},
    {"gltf_short_buffer.gltf", 1, "expected 100000 bytes"},
    {"gltf_huge_count.gltf", 1, "out of range"},
    {"gltf_negative_count.gltf", 1, "count"},
    {"gltf_bad_buffer_view.gltf", 1, "out of bounds"},
    {"gltf_bad_base64.gltf", 1, "cannot read model"},
    {"gltf_mesh_out_of_range.gltf", 1, "out of bounds"},
    {"gltf_node_cycle.gltf", 1, "recursive reference"},
    {"glb_wrong_magic.glb", 1, "cannot read model"},
    {"glb_truncated.glb", 1, "declares 1480 bytes but the file has 20"},
    {"glb_huge_chunk.glb", 1, "truncated or corrupt"},
    {"obj_face_out_of_range.obj", 1, "index out of range"},
    {"obj_negative_index.obj", 1, "index out of range"},
    {"obj_only_vertices.obj", 1, "no triangles"},
    {"obj_garbage.obj", 1, "no triangles"},
    {"obj_empty.obj", 1, "cannot read model"},
    {"obj_infinite_vertex.obj", 1, "non-finite"},
    {"obj_mtl_before_newmtl.obj", 1, "line 2 says 'map_Kd' before any 'newmtl'"},
    // Fallbacks.
    {"gltf_bad_indices.gltf", 0, "out-of-range indices. Those faces were dropped"},
    {"gltf_missing_texture.gltf", 0, "nothere.png' of material 'material 0' not found"},
    {"gltf_corrupt_texture.gltf", 0, "cannot be decoded"},
    {"gltf_huge_texture.gltf", 0, "cannot be decoded"},
    {"obj_missing_mtl.obj", 0, "Unable to locate material file nothere.mtl"},
    {"obj_unknown_material.obj", 0, "failed to locate material nosuch"},
    {"obj_bad_mtl.obj", 0, "png_truncated.png' of material 'broken' cannot be decoded"},
    {"obj_bad_texcoord_refs.obj", 0, ""},  // Assimp ignores out-of-range vt/vn indices (docs/robustness.md)
};

// Each committed image as the texture of a quad: a warning, the material's colour instead.
const std::vector<std::string> kImages = {"png_truncated.png", "png_wrong_magic.png", "png_huge_dims.png",
                                          "png_zero_size.png", "jpg_truncated.jpg",   "bmp_huge_dims.bmp",
                                          "tga_huge_dims.tga"};

bool finite3(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

void expectSaneScene(const Scene& scene, const std::string& what) {
    EXPECT_GT(scene.triangleCount(), 0u) << what;
    for (const Vertex& v : scene.vertices)
        ASSERT_TRUE(finite3(v.position) && finite3(v.normal) && std::isfinite(v.uv.x) && std::isfinite(v.uv.y)) << what;
    for (std::uint32_t i : scene.indices) ASSERT_LT(i, scene.vertices.size()) << what;
    for (const Material& m : scene.materials) {
        EXPECT_TRUE(finite3(m.baseColor) && finite3(m.emissive) && std::isfinite(m.baseAlpha)) << what << " " << m.name;
        EXPECT_LT(m.baseColorTexture, int(scene.textures.size())) << what;
    }
}

void checkCommand(const fs::path& model, int exitCode, const std::string& mentions) {
    const std::string name = model.filename().string();
    const CommandResult r = runVct("info --scene " + model.string());
    EXPECT_EQ(r.exitCode, exitCode) << name << "\n" << r.output;
    EXPECT_EQ(r.output.find("terminate called"), std::string::npos) << name;
    EXPECT_EQ(r.output.find("engine bug"), std::string::npos) << name << "\n" << r.output;
    EXPECT_EQ(r.output.find("unexpected"), std::string::npos) << name << "\n" << r.output;
    if (exitCode == 1) {
        EXPECT_NE(r.output.find("vct: error: "), std::string::npos) << name << "\n" << r.output;
        EXPECT_NE(r.output.find(name), std::string::npos) << "the error must name the file\n" << r.output;
    } else if (!mentions.empty()) {
        EXPECT_NE(r.output.find("vct: warning: "), std::string::npos) << name << "\n" << r.output;
    }
    EXPECT_NE(r.output.find(mentions), std::string::npos) << name << ": expected '" << mentions << "' in\n" << r.output;
}

void checkInProcess(const fs::path& model, int exitCode) {
    const std::string name = model.filename().string();
    for (bool sanitize : {false, true}) {
        try {
            const Scene scene = loadModelFile(model, LoadOptions{sanitize});
            if (!(sanitize && name == "obj_infinite_vertex.obj"))  // --sanitize drops its bad triangle
                EXPECT_EQ(exitCode, 0) << name << " loaded, but the command fails on it";
            expectSaneScene(scene, name);
        } catch (const Error& e) {
            if (!(sanitize && name == "obj_infinite_vertex.obj")) EXPECT_EQ(exitCode, 1) << name << ": " << e.what();
        } catch (const std::exception& e) {
            ADD_FAILURE() << name << ": not a vct::Error: " << e.what();
        }
    }
}

}  // namespace

TEST(StressBadFiles, MalformedModelsEndInAClearErrorOrADocumentedFallback) {
    ASSERT_TRUE(fs::is_directory(kBad)) << kBad;
    std::size_t errors = 0, fallbacks = 0;
    for (const Expectation& e : kModels) {
        ASSERT_TRUE(fs::exists(kBad / e.file)) << e.file;
        checkCommand(kBad / e.file, e.exitCode, e.mentions);
        checkInProcess(kBad / e.file, e.exitCode);
        (e.exitCode ? errors : fallbacks)++;
    }
    // Every model file of the corpus has an expectation.
    std::size_t models = 0;
    for (const auto& entry : fs::directory_iterator(kBad)) {
        const std::string ext = entry.path().extension().string();
        models += ext == ".gltf" || ext == ".glb" || ext == ".obj";
    }
    EXPECT_EQ(models, kModels.size()) << "a corpus file without an expectation";
    std::printf("[ bad files] %zu malformed models: %zu clear errors, %zu fallbacks with a warning\n", kModels.size(),
                errors, fallbacks);
}

TEST(StressBadFiles, MalformedImagesFallBackToTheMaterialColour) {
    const auto dir = testDir();
    for (const std::string& image : kImages) {
        fs::copy_file(kBad / image, dir / image, fs::copy_options::overwrite_existing);
        std::ofstream(dir / "quad.mtl") << "newmtl textured\nKd 0.2 0.4 0.6\nmap_Kd " << image << "\n";
        std::ofstream(dir / "quad.obj") << "mtllib quad.mtl\nusemtl textured\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                           "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n";
        checkCommand(dir / "quad.obj", 0, image + "' of material 'textured' cannot be decoded");
        const Scene scene = loadModelFile(dir / "quad.obj");
        ASSERT_EQ(scene.materials.size(), 1u);
        EXPECT_EQ(scene.materials[0].baseColorTexture, -1) << image;
        EXPECT_FLOAT_EQ(scene.materials[0].baseColor.y, 0.4f) << image;
        ASSERT_EQ(scene.report.missingTextures.size(), 1u) << image;
    }
    std::printf("[ bad files] %zu malformed images: each a warning, the material colour instead\n", kImages.size());
}

// A texture must not cost far more than its file holds: the 19-byte TGA declaring 9265×12576
// uncompressed texels (466 MB decoded; 3 s and 1 GB before the check) is refused from its header.
TEST(StressBadFiles, OversizedUncompressedImageIsRefusedBeforeDecoding) {
    const auto dir = testDir();
    fs::copy_file(kBad / "tga_huge_dims.tga", dir / "huge.tga", fs::copy_options::overwrite_existing);
    std::ofstream(dir / "quad.mtl") << "newmtl textured\nKd 0.2 0.4 0.6\nmap_Kd huge.tga\n";
    std::ofstream(dir / "quad.obj") << "mtllib quad.mtl\nusemtl textured\nv 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\n";
    const auto start = std::chrono::steady_clock::now();
    const CommandResult r = runVct("info --scene " + (dir / "quad.obj").string());
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("an uncompressed 9265x12576 image needs 349549920 bytes of texels, but the file has 19 "
                            "bytes in all"),
              std::string::npos)
        << r.output;
    EXPECT_LT(seconds, 1.0) << "vct info took " << seconds << " s";
    std::printf("[ bad files] 19-byte TGA declaring 9265x12576 texels refused in %.3f s\n", seconds);
}

// Compressed images: the decoded size is bounded by the file's (kMaxExpansion:1), which real
// images stay far below: a uniform 2048² PNG (16 MiB decoded) still decodes.
TEST(StressBadFiles, CompressedImageExpansionIsBounded) {
    const std::vector<std::uint8_t> header(100, 0);
    const auto refused = vct::implausibleImagePayload(header.data(), header.size(), 8192, 8192);
    ASSERT_TRUE(refused.has_value());
    EXPECT_NE(refused->find("a 8192x8192 image (268435456 bytes decoded) from 100 bytes of file"), std::string::npos)
        << *refused;
    EXPECT_FALSE(vct::implausibleImagePayload(header.data(), header.size(), 1024, 1024).has_value())
        << "4 MiB decoded is always allowed";

    const auto dir = testDir();
    vct::Image8 flat(2048, 2048);
    std::fill(flat.rgba.begin(), flat.rgba.end(), std::uint8_t(200));
    vct::writePng(dir / "flat.png", flat);
    std::string error;
    const auto decoded = vct::decodeImageFile(dir / "flat.png", "flat.png", error);
    EXPECT_TRUE(decoded.has_value()) << error << " (file of " << fs::file_size(dir / "flat.png") << " bytes)";
    std::printf("[ bad files] uniform 2048x2048 PNG: %ju bytes, %.0f:1, decoded\n",
                std::uintmax_t(fs::file_size(dir / "flat.png")), 16777216.0 / double(fs::file_size(dir / "flat.png")));
}

TEST(StressBadFiles, FallbacksRenderAnImage) {
    // The documented fallbacks are not just loadable: they render, without NaN.
    const auto dir = testDir();
    for (const char* file : {"gltf_missing_texture.gltf", "obj_bad_mtl.obj", "gltf_bad_indices.gltf"}) {
        const CommandResult r = runVct(std::string("render -q --scene ") + (kBad / file).string() +
                                       " --width 32 --height 24 --voxel-levels 5 --light-view-res 256 --out " +
                                       (dir / "x.png").string() + " --hdr-out " + (dir / "x.pfm").string());
        ASSERT_EQ(r.exitCode, 0) << file << "\n" << r.output;
        const ImageF image = readHdrImage(dir / "x.pfm");
        EXPECT_EQ(countNonFinite(image.rgba), 0u) << file;
        EXPECT_GT(maxRgb(image), 0.0) << file;
    }
}
