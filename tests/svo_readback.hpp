#pragma once
// Builds a sparse voxel octree in-process on OSMesa and reads everything back to the CPU, so tests
// can compare the GPU's structure and values with tests/reference/.
#include <cmath>
#include <cstring>
#include <map>
#include <memory>
#include <set>
#include <vector>

#include "gl/context.hpp"
#include "pipeline/renderer.hpp"
#include "scene/scene.hpp"

namespace vct::test {

// A fragment's cell word holds packCell's 30 bits and above them where its triangle continues in
// its pixel column (shaders/voxel_common.glsl, COLUMN_CONTINUES_BELOW/ABOVE).
constexpr std::uint32_t kFragmentCellBits = (1u << 30) - 1u;

inline float halfToFloat(std::uint16_t h) {
    const int exponent = (h >> 10) & 31, mantissa = h & 1023;
    const float value = exponent == 0 ? std::ldexp(float(mantissa), -24)
                                      : std::ldexp(float(mantissa | 1024), exponent - 25);
    return (h & 0x8000) ? -value : value;
}

// Renders one frame of `scene` lit by `lights` in-process (16×16 pixels: only the voxel data
// matters) and returns the renderer, whose octree and radiance volume the caller reads back.
// The light-view resolution sets the photons per voxel: 2048² gives hundreds per voxel of a
// lit plane at 64³, 512² about 60 (less noise in the voxels against less time on llvmpipe).
inline std::unique_ptr<Renderer> renderRadianceFrame(Scene& scene, const std::vector<Light>& lights, int voxelLevels,
                                                     int lightViewResolution) {
    scene.lights = lights;
    RenderSettings settings;
    settings.width = 16;
    settings.height = 16;
    settings.voxelLevels = voxelLevels;
    settings.lightViewResolution = lightViewResolution;
    auto renderer = std::make_unique<Renderer>(scene, settings);
    renderer->renderFrame(scene.cameras[0]);
    return renderer;
}

// A brick pool (3D texture of `bricks` bricks per axis, 3³ texels each) as RGBA floats, x fastest.
inline std::vector<float> readBrickPool(const gl::Texture& texture, glm::ivec3 bricks) {
    const glm::ivec3 size = 3 * bricks;
    std::vector<float> values(std::size_t(size.x) * size.y * size.z * 4);
    glGetTextureImage(texture.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(values.size() * 4), values.data());
    return values;
}

template <class T>
std::vector<T> readBuffer(const gl::Buffer& buffer, std::size_t count) {
    std::vector<T> values(count);
    if (count) glGetNamedBufferSubData(buffer.id(), 0, GLsizeiptr(count * sizeof(T)), values.data());
    return values;
}

struct GpuOctreeData {
    int levels = 0;
    std::vector<std::uint32_t> levelStart, levelCount;
    std::vector<std::uint32_t> child, mask, coord, parent, neighbours;
    std::vector<std::uint32_t> cellAlbedo, cellFragments;
    std::vector<float> cellArea;
    std::vector<glm::vec4> rawValue;
    std::vector<float> brickPool;  // RGBA, (3·bx) × (3·by) × (3·bz)
    glm::ivec3 brickPoolBricks{0};
    // Slab opacity (brick_layout.hpp, "Slabs"): cell opacity by axis, RGBA8 (αx, αy, αz, α) per
    // cell; the pools (τ+x, τ+y, τ+z, mean) and (τ−x, τ−y, τ−z, mean), laid out as brickPool.
    std::vector<std::uint32_t> cellOpacity;
    std::vector<float> opacityPlus, opacityMinus;
    // Fragment list: cell and albedo of every fragment.
    std::vector<std::uint32_t> fragmentCell, fragmentAlbedo, fragmentMaterial;  // albedo: the texture's colour
    std::vector<float> fragmentArea;

    std::uint32_t cellIndexOf(std::uint32_t node) const { return node - levelStart[levels]; }
    // Complete brick sample s (i + 3j + 9k) of `node`.
    glm::vec4 brickSample(std::uint32_t node, int s) const { return poolSample(brickPool, node, s); }
    // Sample s of `node` in any pool of the brick layout (brickPool, opacityPlus, opacityMinus).
    glm::vec4 poolSample(const std::vector<float>& pool, std::uint32_t node, int s) const {
        const int b = int(node);
        const glm::ivec3 origin = 3 * glm::ivec3(b % brickPoolBricks.x, (b / brickPoolBricks.x) % brickPoolBricks.y,
                                                 b / (brickPoolBricks.x * brickPoolBricks.y));
        const glm::ivec3 t = origin + glm::ivec3(s % 3, (s / 3) % 3, s / 9);
        const glm::ivec3 size = 3 * brickPoolBricks;
        const std::size_t i = ((std::size_t(t.z) * size.y + t.y) * size.x + t.x) * 4;
        return {pool[i], pool[i + 1], pool[i + 2], pool[i + 3]};
    }
    std::set<std::uint32_t> cellSet() const {
        return {coord.begin() + levelStart[levels], coord.begin() + levelStart[levels] + levelCount[levels]};
    }
};

// Owns a context, uploads `scene`, builds the octree at `levels`.
class SvoHarness {
public:
    explicit SvoHarness(const Scene& scene) : scene_(scene) {
        context_ = gl::createContext(gl::defaultBackend());
    }
    // Through the renderer's own octree passes, as `vct info --voxel-levels` does.
    GpuOctreeData build(int levels) {
        RenderSettings settings;
        settings.width = settings.height = 1;
        settings.voxelLevels = levels;
        renderer_ = std::make_unique<Renderer>(scene_, settings);
        renderer_->buildOctree();
        return read();
    }
    const SvoBuilder& builder() const { return *renderer_->octree(); }

private:
    GpuOctreeData read() const {
        const Octree& o = builder().octree();
        GpuOctreeData d;
        d.levels = o.levels;
        d.levelStart.assign(o.levelStart.begin(), o.levelStart.end());
        d.levelCount.assign(o.levelCount.begin(), o.levelCount.end());
        d.child = readBuffer<std::uint32_t>(o.child, o.totalCount);
        d.mask = readBuffer<std::uint32_t>(o.mask, o.totalCount);
        d.coord = readBuffer<std::uint32_t>(o.coord, o.totalCount);
        d.parent = readBuffer<std::uint32_t>(o.parent, o.totalCount);
        d.neighbours = readBuffer<std::uint32_t>(o.neighbours, std::size_t(o.nodeCount) * 6);
        d.cellAlbedo = readBuffer<std::uint32_t>(o.cellAlbedo, o.cellCount());
        d.cellFragments = readBuffer<std::uint32_t>(o.cellFragments, o.cellCount());
        d.cellArea = readBuffer<float>(o.cellArea, o.cellCount());
        d.rawValue = readBuffer<glm::vec4>(o.rawValue, o.nodeCount);
        d.brickPoolBricks = o.brickPoolBricks;
        const glm::ivec3 size = 3 * o.brickPoolBricks;
        d.brickPool.resize(std::size_t(size.x) * size.y * size.z * 4);
        glGetTextureImage(o.brickAlbedo.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(d.brickPool.size() * 4), d.brickPool.data());
        d.cellOpacity = readBuffer<std::uint32_t>(o.cellOpacity, o.cellCount());
        d.opacityPlus = readBrickPool(o.brickOpacityPlus, o.brickPoolBricks);
        d.opacityMinus = readBrickPool(o.brickOpacityMinus, o.brickPoolBricks);
        const FragmentList& f = builder().fragments();
        const auto raw = readBuffer<std::uint32_t>(f.data, std::size_t(f.count) * 4);
        for (std::size_t i = 0; i < f.count; ++i) {
            d.fragmentCell.push_back(raw[i * 4] & kFragmentCellBits);
            d.fragmentAlbedo.push_back(raw[i * 4 + 1]);
            d.fragmentMaterial.push_back(raw[i * 4 + 3] >> 16);
            d.fragmentArea.push_back(halfToFloat(std::uint16_t(raw[i * 4 + 3] & 0xFFFF)));
        }
        return d;
    }

    const Scene& scene_;
    std::unique_ptr<gl::Context> context_;
    std::unique_ptr<Renderer> renderer_;
};

// A scene made of raw triangles with one material per triangle group, inside given bounds.
inline Scene makeTriangleScene(const std::vector<glm::dvec3>& positions, const Bounds& bounds,
                               const std::vector<std::pair<std::size_t, glm::vec3>>& groups = {}) {
    Scene scene;
    scene.name = "triangles";
    scene.worldBounds = bounds;
    scene.origin = bounds.centre();
    for (const glm::dvec3& p : positions) {
        Vertex v;
        v.position = glm::vec3(p - scene.origin);
        v.normal = {0, 0, 1};
        v.uv = {0, 0};
        scene.vertices.push_back(v);
        scene.indices.push_back(std::uint32_t(scene.indices.size()));
    }
    if (groups.empty()) {
        scene.materials.push_back(Material{"white", glm::vec3(0.8f)});
        scene.drawRanges.push_back({0, std::uint32_t(scene.indices.size()), 0});
    } else {
        std::uint32_t first = 0;
        for (const auto& [triangles, albedo] : groups) {
            scene.drawRanges.push_back({first, std::uint32_t(triangles * 3), std::uint32_t(scene.materials.size())});
            scene.materials.push_back(Material{"group", albedo});
            first += std::uint32_t(triangles * 3);
        }
    }
    scene.cameras.push_back(Camera{});
    return scene;
}

}  // namespace vct::test
