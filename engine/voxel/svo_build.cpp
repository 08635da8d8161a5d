#include "voxel/svo_build.hpp"

#include <algorithm>

#include "core/error.hpp"
#include "gl/compute.hpp"

namespace vct {
namespace {
constexpr GLbitfield kStorage = GL_DYNAMIC_STORAGE_BIT;
constexpr std::uint32_t kNone = 0xFFFFFFFFu;

gl::Buffer grow(const gl::Buffer& old, std::size_t oldBytes, std::size_t newBytes, const char* label) {
    gl::Buffer bigger = gl::createBuffer(GLsizeiptr(newBytes), nullptr, kStorage, label);
    if (old && oldBytes) glCopyNamedBufferSubData(old.id(), bigger.id(), 0, 0, GLsizeiptr(oldBytes));
    return bigger;
}
}  // namespace

SvoBuild::SvoBuild()
    : flag_(gl::buildProgram({{GL_COMPUTE_SHADER, "svo_flag.comp"}})),
      alloc_(gl::buildProgram({{GL_COMPUTE_SHADER, "svo_alloc.comp"}})),
      init_(gl::buildProgram({{GL_COMPUTE_SHADER, "svo_init.comp"}})),
      descend_(gl::buildProgram({{GL_COMPUTE_SHADER, "svo_descend.comp"}})) {}

void SvoBuild::ensureCapacity(Octree& octree, std::uint32_t nodes) {
    if (nodes <= poolCapacity_) return;
    const std::uint32_t capacity = std::max<std::uint32_t>(nodes, poolCapacity_ + poolCapacity_ / 2);
    GLint maxBlock = 0;
    glGetIntegerv(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxBlock);
    if (std::uint64_t(capacity) * 4 > std::uint64_t(maxBlock))
        fail("the octree needs ", nodes, " nodes, more than this GPU's storage blocks hold (", maxBlock / 4,
             "); lower --voxel-levels");
    const std::size_t oldBytes = std::size_t(poolCapacity_) * 4, newBytes = std::size_t(capacity) * 4;
    octree.child = grow(octree.child, oldBytes, newBytes, "octree child");
    octree.mask = grow(octree.mask, oldBytes, newBytes, "octree mask");
    octree.coord = grow(octree.coord, oldBytes, newBytes, "octree coord");
    octree.parent = grow(octree.parent, oldBytes, newBytes, "octree parent");
    poolCapacity_ = capacity;
    gl::checkErrors(concat("growing the octree node pool to ", capacity, " nodes"));
}

void SvoBuild::run(const FragmentList& fragments, const VoxelGrid& grid, Octree& octree) {
    octree.grid = grid;
    octree.levels = grid.levels;
    octree.levelStart.fill(0);
    octree.levelCount.fill(0);
    octree.child.reset();
    octree.mask.reset();
    octree.coord.reset();
    octree.parent.reset();
    poolCapacity_ = 0;
    ensureCapacity(octree, std::max<std::uint32_t>(4096, fragments.count / 2));
    const std::uint32_t none = kNone, zero = 0;
    glNamedBufferSubData(octree.child.id(), 0, 4, &none);
    glNamedBufferSubData(octree.mask.id(), 0, 4, &zero);
    glNamedBufferSubData(octree.coord.id(), 0, 4, &zero);
    glNamedBufferSubData(octree.parent.id(), 0, 4, &none);
    octree.levelCount[0] = 1;

    fragmentNode_ = gl::createBuffer(GLsizeiptr(std::max<std::uint32_t>(fragments.count, 1)) * 4, nullptr, 0,
                                     "fragment node");
    fragmentNodeTexture_ = gl::createTexture(GL_TEXTURE_BUFFER, "fragment node");
    glTextureBuffer(fragmentNodeTexture_.id(), GL_R32UI, fragmentNode_.id());

    const GLbitfield barrier = GL_SHADER_STORAGE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT;
    // One invocation per fragment: flag marks child slots, descend moves the fragment down.
    auto overFragments = [&](const gl::Program& program, int level) {
        gl::ComputeCall call(program);
        octree.bind(call.program());
        call.uniform("uFragmentCount", fragments.count)
            .uniform("uLevel", level)
            .image(gl::IMAGE_FRAGMENTS, fragments.dataTexture.id(), GL_READ_ONLY, GL_RGBA32UI)
            .image(gl::IMAGE_FRAGMENT_NODE, fragmentNodeTexture_.id(), GL_READ_WRITE, GL_R32UI)
            .dispatch1D(fragments.count, 64, barrier);
    };
    // One invocation per node of the level.
    auto overNodes = [&](const gl::Program& program, int level, int phase) {
        gl::ComputeCall call(program);
        octree.bind(call.program());
        call.uniform("uLevel", level)
            .uniform("uPhase", phase)
            .storage(gl::SSBO_CHILD_COUNTS, counts_)
            .dispatch1D(octree.levelCount[level], 64, barrier);
    };

    for (int level = 0; level < grid.levels; ++level) {
        const std::uint32_t count = octree.levelCount[level];
        overFragments(flag_, level);
        if (count > countsCapacity_) {
            countsCapacity_ = std::max(count, countsCapacity_ * 2);
            counts_ = gl::createBuffer(GLsizeiptr(countsCapacity_) * 4, nullptr, kStorage, "octree child counts");
        }
        overNodes(alloc_, level, 0);
        const std::uint32_t children = prefixSum_.scan(counts_.id(), count);
        octree.levelStart[level + 1] = octree.levelStart[level] + count;
        octree.levelCount[level + 1] = children;
        ensureCapacity(octree, octree.levelStart[level + 1] + children);
        overNodes(alloc_, level, 1);
        overNodes(init_, level, 0);
        overFragments(descend_, level);
    }
    octree.nodeCount = octree.levelStart[grid.levels];
    octree.totalCount = octree.nodeCount + octree.levelCount[grid.levels];

    // Trim the pool to the exact size (DESIGN: sized by the per-level counts, not a full tree).
    const std::size_t bytes = std::size_t(octree.totalCount) * 4;
    for (gl::Buffer* buffer : {&octree.child, &octree.mask, &octree.coord, &octree.parent}) {
        gl::Buffer exact = gl::createBuffer(GLsizeiptr(bytes), nullptr, kStorage, "octree nodes");
        glCopyNamedBufferSubData(buffer->id(), exact.id(), 0, 0, GLsizeiptr(bytes));
        *buffer = std::move(exact);
    }
    poolCapacity_ = octree.totalCount;
    gl::checkErrors("building the octree");
}

}  // namespace vct
