// `vct info`: what a scene contains (counts, bounds, presets, lights, what loading repaired) and,
// with --gl, what the OpenGL context offers.
#include <cstdio>

#include "cli/commands.hpp"
#include "cli/scene_options.hpp"
#include "core/error.hpp"
#include "gl/context.hpp"
#include "gl/gl.hpp"
#include "pipeline/renderer.hpp"

namespace vct::cli {
namespace {

struct InfoOptions {
    SceneOptions scene;
    bool gl = false;
    std::string backend = gl::defaultBackendName();
    int voxelLevels = 0;
};

void printVec(const char* label, const glm::dvec3& v) { std::printf("%s(%.6g, %.6g, %.6g)", label, v.x, v.y, v.z); }

void run(const InfoOptions& o) {
    const Scene scene = loadSceneFromOptions(o.scene);
    std::size_t textureBytes = 0;
    for (const auto& t : scene.textures) textureBytes += t.rgba.size();
    std::size_t masked = 0, emissive = 0;
    for (const auto& m : scene.materials) {
        masked += m.alphaMode == AlphaMode::Mask;
        emissive += m.emissive != glm::vec3(0.0f);
    }
    std::printf("scene      %s%s%s\n", scene.name.c_str(), scene.sourcePath.empty() ? "" : "  ",
                scene.sourcePath.c_str());
    std::printf("triangles  %zu\nvertices   %zu\n", scene.triangleCount(), scene.vertices.size());
    std::printf("materials  %zu (%zu alpha-masked, %zu emissive)\n", scene.materials.size(), masked, emissive);
    std::printf("textures   %zu (%.1f MiB decoded)\n", scene.textures.size(), textureBytes / 1048576.0);
    printVec("bounds     min ", scene.worldBounds.min);
    printVec("  max ", scene.worldBounds.max);
    printVec("\nsize       ", scene.worldBounds.size());
    std::printf("\n");
    std::printf("cameras   ");
    for (const auto& c : scene.cameras) std::printf(" %s", c.name.c_str());
    std::printf("\nlights     %zu\n", scene.lights.size());
    for (const auto& l : scene.lights) std::printf("  %s\n", describe(l).c_str());
    const LoadReport& r = scene.report;
    std::printf("load report: %zu source triangles, %zu degenerate removed, %zu dropped (non-finite), "
                "%zu normals repaired, %zu UVs repaired, %zu missing textures\n",
                r.sourceTriangles, r.degenerateTriangles, r.droppedTriangles, r.repairedNormals, r.repairedUvs,
                r.missingTextures.size());
    for (const auto& t : r.missingTextures) std::printf("  missing texture: %s\n", t.c_str());
    for (const auto& f : r.unsupportedFeatures) std::printf("  not supported: %s\n", f.c_str());
    if (o.voxelLevels) {
        // The octree's real size: build it (on the GPU, through the frame's own passes) and measure.
        auto context = gl::createContext(gl::parseBackend(o.backend));
        RenderSettings settings;
        settings.width = settings.height = 1;
        settings.voxelLevels = o.voxelLevels;
        validateRenderSettings(settings);
        Renderer renderer(scene, settings);
        renderer.buildOctree();
        const SvoBuilder& builder = *renderer.octree();
        const VoxelGrid& grid = builder.octree().grid;
        std::printf("voxel grid        %d³, voxel size %.6g (scene units)\n", grid.resolution(), grid.voxelSize);
        std::printf("%s", formatVoxelMemory(builder.memory()).c_str());
    }
    if (o.gl) {
        auto context = gl::createContext(gl::parseBackend(o.backend));
        const auto& info = context->info();
        std::printf("gl         %s | %s | %s | GLSL %s\n", info.backend.c_str(), info.vendor.c_str(),
                    info.renderer.c_str(), info.version.c_str());
        auto limit = [](const char* name, GLenum e) {
            GLint v = 0;
            glGetIntegerv(e, &v);
            std::printf("  %-36s %d\n", name, v);
        };
        limit("GL_MAX_TEXTURE_SIZE", GL_MAX_TEXTURE_SIZE);
        limit("GL_MAX_3D_TEXTURE_SIZE", GL_MAX_3D_TEXTURE_SIZE);
        limit("GL_MAX_SHADER_STORAGE_BLOCK_SIZE", GL_MAX_SHADER_STORAGE_BLOCK_SIZE);
        limit("GL_MAX_TEXTURE_BUFFER_SIZE", GL_MAX_TEXTURE_BUFFER_SIZE);
    }
}

}  // namespace

Run addInfoCommand(CLI::App& app) {
    auto options = std::make_shared<InfoOptions>();
    CLI::App* command = app.add_subcommand("info", "print what a scene contains (and, with --gl, the GL limits)");
    addSceneOptions(*command, options->scene, false);
    command->add_flag("--gl", options->gl, "also create a context and print renderer and limits");
    command->add_option("--backend", options->backend, "backend for --gl and --voxel-levels")->capture_default_str();
    command->add_option("--voxel-levels", options->voxelLevels,
                        "build the octree at 2^L voxels per axis and report its nodes per level and memory");
    return [options] { run(*options); };
}

}  // namespace vct::cli
