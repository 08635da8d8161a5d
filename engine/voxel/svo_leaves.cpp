#include "voxel/svo_leaves.hpp"

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
    gl::Buffer accumulators =
        gl::createBuffer(GLsizeiptr(cells) * kAccumulatorFields * 4, nullptr, GL_DYNAMIC_STORAGE_BIT, "cell accumulators");
    const std::uint32_t zero = 0;
    glClearNamedBufferData(accumulators.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    gl::Texture accumulatorTexture = gl::createTexture(GL_TEXTURE_BUFFER, "cell accumulators");
    glTextureBuffer(accumulatorTexture.id(), GL_R32UI, accumulators.id());
    gl::Buffer projected =
        gl::createBuffer(GLsizeiptr(cells) * kProjectedFields * 4, nullptr, GL_DYNAMIC_STORAGE_BIT, "cell projected areas");
    glClearNamedBufferData(projected.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    gl::Texture projectedTexture = gl::createTexture(GL_TEXTURE_BUFFER, "cell projected areas");
    glTextureBuffer(projectedTexture.id(), GL_R32UI, projected.id());

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
    octree.cellAlbedo = gl::createBuffer(bytes, nullptr, 0, "cell albedo");
    octree.cellNormal = gl::createBuffer(bytes, nullptr, 0, "cell normal");
    octree.cellArea = gl::createBuffer(bytes, nullptr, 0, "cell area");
    octree.cellFragments = gl::createBuffer(bytes, nullptr, 0, "cell fragments");
    octree.cellColumns = gl::createBuffer(bytes, nullptr, 0, "cell column partners");
    octree.cellOpacity = gl::createBuffer(bytes, nullptr, 0, "cell opacity by axis");
    if (emissive) octree.cellEmissive = gl::createBuffer(bytes * 4, nullptr, 0, "cell emission");
    else octree.cellEmissive.reset();
    gl::Buffer status = gl::createBuffer(8, nullptr, GL_DYNAMIC_STORAGE_BIT, "leaf status");
    const std::uint32_t zeros[2] = {0, 0};
    glNamedBufferSubData(status.id(), 0, 8, zeros);

    gl::ComputeCall normalize(normalize_);
    octree.bind(normalize.program());
    normalize.uniform("uHasEmissive", emissive ? 1 : 0)
        .uniform("uEmissiveScale", emissiveScale)
        .image(gl::IMAGE_CELL_ACCUMULATORS, accumulatorTexture.id(), GL_READ_ONLY, GL_R32UI)
        .image(gl::IMAGE_PROJECTED_AREA, projectedTexture.id(), GL_READ_ONLY, GL_R32UI)
        .storage(gl::SSBO_LEAF_STATUS, status)
        .storage(gl::SSBO_CELL_VALUES, octree.cellAlbedo)
        .storage(gl::SSBO_CELL_NORMAL, octree.cellNormal)
        .storage(gl::SSBO_CELL_AREA, octree.cellArea)
        .storage(gl::SSBO_CELL_FRAGMENTS, octree.cellFragments)
        .storage(gl::SSBO_CELL_COLUMNS, octree.cellColumns)
        .storage(gl::SSBO_CELL_OPACITY, octree.cellOpacity);
    if (emissive) normalize.storage(gl::SSBO_CELL_EMISSIVE, octree.cellEmissive);
    normalize.dispatch1D(cells, 64, barrier | GL_BUFFER_UPDATE_BARRIER_BIT);

    std::uint32_t result[2] = {0, 0};
    glGetNamedBufferSubData(status.id(), 0, 8, result);
    if (result[0] > 0)
        fail(result[0], " voxels received more than 16,843,009 fragments each (largest: ", result[1],
             "); their 32-bit sums would overflow. Lower --voxel-levels or simplify the model");
    gl::checkErrors("computing the octree's cell values");
    return {result[1]};
}

}  // namespace vct
