#include "voxel/voxelize.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/log.hpp"
#include "gl/driver_checks.hpp"
#include "gl/raster_state.hpp"
#include "gl/shader.hpp"
#include "gl/shader_interface.hpp"

namespace vct {

Voxelizer::Voxelizer()
    : program_(gl::buildProgram({{GL_VERTEX_SHADER, "voxelize.vert"},
                                 {GL_GEOMETRY_SHADER, "voxelize.geom"},
                                 {GL_FRAGMENT_SHADER, "voxelize.frag"}})),
      framebuffer_(gl::createFramebuffer("voxelize")) {}

std::uint64_t estimateFragments(const Scene& scene, const VoxelGrid& grid) {
    double area = 0.0;
    for (std::size_t t = 0; t < scene.indices.size(); t += 3) {
        const glm::dvec3 a(scene.vertices[scene.indices[t]].position);
        const glm::dvec3 b(scene.vertices[scene.indices[t + 1]].position);
        const glm::dvec3 c(scene.vertices[scene.indices[t + 2]].position);
        area += 0.5 * glm::length(glm::cross(b - a, c - a));
    }
    const double voxelArea = grid.voxelSize * grid.voxelSize;
    return std::uint64_t(3.0 * area / voxelArea + 4.0 * double(scene.triangleCount())) + 1024;
}

void Voxelizer::allocate(FragmentList& list, std::uint32_t capacity) const {
    GLint maxTexels = 0;
    glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &maxTexels);
    if (std::uint64_t(capacity) > std::uint64_t(maxTexels))
        fail("the voxel-fragment list needs ", capacity, " fragments but this GPU's buffer textures hold at most ",
             maxTexels, "; lower --voxel-levels");
    list.data = gl::createBuffer(GLsizeiptr(capacity) * 16, nullptr, 0, "voxel fragments");
    list.dataTexture = gl::createTexture(GL_TEXTURE_BUFFER, "voxel fragments");
    glTextureBuffer(list.dataTexture.id(), GL_RGBA32UI, list.data.id());
    list.capacity = capacity;
    gl::checkErrors(concat("allocating the voxel-fragment list (", capacity, " fragments)"));
}

void Voxelizer::run(const GpuScene& gpuScene, const Scene& scene, const VoxelGrid& grid, FragmentList& list) {
    if (!list.counter)
        list.counter = gl::createBuffer(4, nullptr, GL_DYNAMIC_STORAGE_BIT, "voxel fragment counter");
    if (list.capacity == 0) {
        const std::uint64_t estimate = std::min<std::uint64_t>(estimateFragments(scene, grid), 1u << 26);
        allocate(list, std::uint32_t(estimate));
    }
    list.regrowths = 0;
    const int n = grid.resolution();
    glNamedFramebufferParameteri(framebuffer_.id(), GL_FRAMEBUFFER_DEFAULT_WIDTH, n);
    glNamedFramebufferParameteri(framebuffer_.id(), GL_FRAMEBUFFER_DEFAULT_HEIGHT, n);
    const GLuint p = program_.id();
    for (;;) {
        const std::uint32_t zero = 0;
        glNamedBufferSubData(list.counter.id(), 0, 4, &zero);
        // No attachments: the viewport is the voxel grid's face; fragments append to the list.
        gl::beginRasterPass({framebuffer_.id(), n, n, false});
        glUseProgram(p);
        gl::setUniform(p, "uVoxelOrigin", glm::vec3(grid.localMin));
        gl::setUniform(p, "uVoxelScale", float(1.0 / grid.voxelSize));
        gl::setUniform(p, "uViewportSize", float(n));
        gl::setUniform(p, "uResolution", n);
        gl::setUniform(p, "uCapacity", list.capacity);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, gl::SSBO_FRAGMENT_COUNTER, list.counter.id());
        glBindImageTexture(gl::IMAGE_FRAGMENTS, list.dataTexture.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32UI);
        gpuScene.draw(p);
        gl::endRasterPass();
        gl::memoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                          GL_BUFFER_UPDATE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
        std::uint32_t count = 0;
        glGetNamedBufferSubData(list.counter.id(), 0, 4, &count);
        if (count <= list.capacity) {
            list.count = count;
            break;
        }
        logInfo(concat("voxel-fragment list: ", count, " fragments for a capacity of ", list.capacity,
                       "; growing it and voxelizing again"));
        allocate(list, count);
        ++list.regrowths;
    }
    gl::checkErrors("voxelizing the scene");
}

}  // namespace vct
