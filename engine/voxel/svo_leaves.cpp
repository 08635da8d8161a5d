#include "voxel/svo_leaves.hpp"

#include <algorithm>

#include "core/error.hpp"
#include "gl/compute.hpp"

namespace vct {
namespace {
constexpr std::uint32_t kAccumulatorFields = gl::CELL_ACCUMULATOR_FIELDS;
// Area projected along x, y, z as 64-bit sums, in a buffer of its own so that the octree's
// largest cell count stays what the main accumulators' buffer-texture limit allows.
constexpr std::uint32_t kProjectedFields = gl::PROJECTED_AREA_FIELDS;
}

SvoLeaves::SvoLeaves()
    : accumulate_(gl::buildProgram({{GL_COMPUTE_SHADER, "svo_leaves_accumulate.comp"}})),
      normalize_(gl::buildProgram({{GL_COMPUTE_SHADER, "svo_leaves_normalize.comp"}})) {}

LeafStatistics SvoLeaves::run(const FragmentList& fragments, GLuint fragmentNodeTexture, const GpuScene& gpuScene,
                              Octree& octree) {
    const float maxEmission = gpuScene.maxEmission();
    const bool emissive = maxEmission > 0.0f;
    const std::uint32_t cells = octree.cellCount();
    GLint maxTexels = 0;
    glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &maxTexels);
    if (std::uint64_t(cells) * kAccumulatorFields > std::uint64_t(maxTexels))
        fail("the octree has ", cells, " occupied cells; their accumulators exceed this GPU's buffer-texture limit (",
             maxTexels / kAccumulatorFields, " cells); lower --voxel-levels");
    // The sums' views cover exactly the cells: a kept buffer may be larger (gl::fitBuffer).
    const GLsizeiptr accumulatorBytes = GLsizeiptr(cells) * kAccumulatorFields * 4;
    const GLsizeiptr projectedBytes = GLsizeiptr(cells) * kProjectedFields * 4;
    gl::fitBuffer(accumulators_, accumulatorBytes, GL_DYNAMIC_STORAGE_BIT, "cell accumulators");
    gl::fitBuffer(projected_, projectedBytes, GL_DYNAMIC_STORAGE_BIT, "cell projected areas");
    const std::uint32_t zero = 0;
    glClearNamedBufferSubData(accumulators_.id(), GL_R32UI, 0, accumulatorBytes, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    glClearNamedBufferSubData(projected_.id(), GL_R32UI, 0, projectedBytes, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    gl::Texture accumulatorTexture = gl::createTexture(GL_TEXTURE_BUFFER, "cell accumulators");
    glTextureBufferRange(accumulatorTexture.id(), GL_R32UI, accumulators_.id(), 0, std::max<GLsizeiptr>(accumulatorBytes, 4));
    gl::Texture projectedTexture = gl::createTexture(GL_TEXTURE_BUFFER, "cell projected areas");
    glTextureBufferRange(projectedTexture.id(), GL_R32UI, projected_.id(), 0, std::max<GLsizeiptr>(projectedBytes, 4));

    octree.hasEmissive = emissive;
    const float emissiveScale = maxEmission > 0.0f ? 16777216.0f / maxEmission : 0.0f;
    const GLbitfield barrier = GL_SHADER_STORAGE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT;

    gl::ComputeCall accumulate(accumulate_);
    octree.bind(accumulate.program());
    accumulate.uniform("uFragmentCount", fragments.count)
        .uniform("uHasEmissive", emissive ? 1 : 0)
        .uniform("uEmissiveScale", emissiveScale)
        .image(gl::IMAGE_FRAGMENTS, fragments.dataTexture.id(), GL_READ_ONLY, GL_RGBA32UI)
        .image(gl::IMAGE_FRAGMENT_NODE, fragmentNodeTexture, GL_READ_ONLY, GL_R32UI)
        .storage(gl::SSBO_MATERIALS, gpuScene.materialBuffer())
        .image(gl::IMAGE_CELL_ACCUMULATORS, accumulatorTexture.id(), GL_READ_WRITE, GL_R32UI)
        .image(gl::IMAGE_PROJECTED_AREA, projectedTexture.id(), GL_READ_WRITE, GL_R32UI)
        .dispatch1D(fragments.count, 64, barrier);

    const GLsizeiptr bytes = GLsizeiptr(std::max<std::uint32_t>(cells, 1)) * 4;
    gl::fitBuffer(octree.cellAlbedo, bytes, 0, "cell albedo");
    gl::fitBuffer(octree.cellNormal, bytes, 0, "cell normal");
    gl::fitBuffer(octree.cellArea, bytes, 0, "cell area");
    gl::fitBuffer(octree.cellFragments, bytes, 0, "cell fragments");
    gl::fitBuffer(octree.cellColumns, bytes, 0, "cell column partners");
    gl::fitBuffer(octree.cellOpacity, bytes, 0, "cell opacity by axis");
    if (emissive) gl::fitBuffer(octree.cellEmissive, bytes * 4, 0, "cell emission");
    else octree.cellEmissive.reset();
    if (!status_) status_ = gl::createBuffer(8, nullptr, GL_DYNAMIC_STORAGE_BIT, "leaf status");
    const std::uint32_t zeros[2] = {0, 0};
    glNamedBufferSubData(status_.id(), 0, 8, zeros);

    gl::ComputeCall normalize(normalize_);
    octree.bind(normalize.program());
    normalize.uniform("uHasEmissive", emissive ? 1 : 0)
        .uniform("uEmissiveScale", emissiveScale)
        .image(gl::IMAGE_CELL_ACCUMULATORS, accumulatorTexture.id(), GL_READ_ONLY, GL_R32UI)
        .image(gl::IMAGE_PROJECTED_AREA, projectedTexture.id(), GL_READ_ONLY, GL_R32UI)
        .storage(gl::SSBO_LEAF_STATUS, status_)
        .storage(gl::SSBO_CELL_VALUES, octree.cellAlbedo)
        .storage(gl::SSBO_CELL_NORMAL, octree.cellNormal)
        .storage(gl::SSBO_CELL_AREA, octree.cellArea)
        .storage(gl::SSBO_CELL_FRAGMENTS, octree.cellFragments)
        .storage(gl::SSBO_CELL_COLUMNS, octree.cellColumns)
        .storage(gl::SSBO_CELL_OPACITY, octree.cellOpacity);
    if (emissive) normalize.storage(gl::SSBO_CELL_EMISSIVE, octree.cellEmissive);
    normalize.dispatch1D(cells, 64, barrier | GL_BUFFER_UPDATE_BARRIER_BIT);

    std::uint32_t result[2] = {0, 0};
    glGetNamedBufferSubData(status_.id(), 0, 8, result);
    if (result[0] > 0)
        fail(result[0], " voxels received more than 16,843,009 fragments each (largest: ", result[1],
             "); their 32-bit sums would overflow. Lower --voxel-levels or simplify the model");
    gl::checkErrors("computing the octree's cell values");
    return {result[1]};
}

}  // namespace vct
