#include "lighting/radiance_filter.hpp"

#include <cstdlib>
#include <string>

#include "core/error.hpp"
#include "gl/driver_checks.hpp"
#include "voxel/brick_pool.hpp"

namespace vct {
namespace {
constexpr GLbitfield kBarrier =
    GL_SHADER_STORAGE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT;

// The invocations of the work group that filters one node (radiance_leaves.comp,
// radiance_mip.comp): 64 on a GPU, where sharing the node's neighbourhood among them ran 7–8×
// faster than one invocation per node; 8 on a CPU rasterizer, one SIMD batch of llvmpipe's, whose
// barriers then cost little (64 cost it a quarter more). VCT_NODE_GROUP_SIZE (1..64) sets it, so
// that the GPU's size is checked on any machine: every size gives the same bits.
std::string nodeGroupDefine() {
    int size = gl::cpuRasterizer() ? 8 : 64;
    if (const char* forced = std::getenv("VCT_NODE_GROUP_SIZE"); forced && *forced) {
        char* end = nullptr;
        const long value = std::strtol(forced, &end, 10);
        if (*end != '\0' || value < 1 || value > 64)
            fail("VCT_NODE_GROUP_SIZE must be a whole number from 1 to 64 (invocations per node of the radiance "
                 "filter), not '", forced, "'; unset it to let vct choose");
        size = int(value);
    }
    return "NODE_GROUP_SIZE " + std::to_string(size);
}

gl::ComputeCall over(const gl::Program& program, const Octree& octree, const RadianceVolume& volume, int level) {
    gl::ComputeCall call = brickLevelCall(program, octree, level);
    bindRadianceVolume(volume);
    return call;
}
}  // namespace

RadianceFilter::RadianceFilter()
    : ageBorder_(gl::buildProgram({{GL_COMPUTE_SHADER, "border_age.comp"}})),
      clear_(gl::buildProgram({{GL_COMPUTE_SHADER, "radiance_clear.comp"}})),
      clearBorder_(gl::buildProgram({{GL_COMPUTE_SHADER, "radiance_clear.comp"}}, {"CLEAR_BORDER 1"})),
      touchParents_(gl::buildProgram({{GL_COMPUTE_SHADER, "touch_parents.comp"}})),
      touchBorder_(gl::buildProgram({{GL_COMPUTE_SHADER, "touch_border.comp"}})),
      leaves_(gl::buildProgram({{GL_COMPUTE_SHADER, "radiance_leaves.comp"}}, {nodeGroupDefine()})),
      mip_(gl::buildProgram({{GL_COMPUTE_SHADER, "radiance_mip.comp"}}, {nodeGroupDefine()})),
      share_(gl::buildProgram({{GL_COMPUTE_SHADER, "radiance_share.comp"}})) {}

void RadianceFilter::leaves(const Octree& octree, RadianceVolume& volume) {
    // Bricks outside the border lists are not written again: they must read as no light. Only the
    // last filtering's border nodes can hold light; every node, the first time over these geometry
    // bricks (their density is what "no light" holds, and the flags hold nothing yet).
    const bool onlyBorder =
        volume.darkOutsideBorderFor != 0 && volume.darkOutsideBorderFor == octree.geometryBricksBuild;
    if (onlyBorder) {
        gl::ComputeCall age = over(ageBorder_, octree, volume, 0);
        age.uniform("uNodeCount", octree.nodeCount).dispatch1D(octree.nodeCount, 64, kBarrier);
    } else {
        const std::uint32_t zero = 0;
        glClearNamedBufferData(volume.borderFlag.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    }
    clearListCounts(volume, gl::BORDER_COUNT_SLOT, gl::MISSED_COUNT_SLOT);
    gl::memoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);

    for (int level = octree.levels - 1; level >= 0; --level)
        listDispatch_.dispatch(over(touchParents_, octree, volume, level), volume,
                               kTouchedCountSlot + unsigned(level + 1), kBarrier);
    for (int level = 0; level < octree.levels; ++level)
        listDispatch_.dispatch(over(touchBorder_, octree, volume, level), volume, kTouchedCountSlot + unsigned(level),
                               kBarrier);
    // With the border known, the bricks that will not be written again.
    gl::ComputeCall clear = over(onlyBorder ? clearBorder_ : clear_, octree, volume, 0);
    clear.uniform("uNodeCount", octree.nodeCount)
        .texture(gl::TEXTURE_OPACITY_PLUS, octree.brickOpacityPlus.id())
        .texture(gl::TEXTURE_OPACITY_MINUS, octree.brickOpacityMinus.id());
    bindDirectionalImage(clear, volume, GL_WRITE_ONLY);
    clear.dispatch1D(octree.nodeCount, 64, kBarrier);
    volume.darkOutsideBorderFor = octree.geometryBricksBuild;

    const int leafLevel = octree.levels - 1;
    gl::ComputeCall call = over(leaves_, octree, volume, leafLevel);
    call.storage(gl::SSBO_CELL_OPACITY, octree.cellOpacity)
        .texture(gl::TEXTURE_OPACITY_PLUS, octree.brickOpacityPlus.id())
        .texture(gl::TEXTURE_OPACITY_MINUS, octree.brickOpacityMinus.id());
    bindDirectionalImage(call, volume, GL_WRITE_ONLY);
    listDispatch_.dispatch(call, volume, kBorderCountSlot + unsigned(leafLevel), kBarrier, 1);  // a group per node
    gl::checkErrors("filling the leaves' radiance bricks");
}

void RadianceFilter::mip(const Octree& octree, RadianceVolume& volume) {
    for (int level = octree.levels - 2; level >= 0; --level) {
        gl::ComputeCall call = over(mip_, octree, volume, level);
        call.texture(gl::TEXTURE_OPACITY_PLUS, octree.brickOpacityPlus.id())
            .texture(gl::TEXTURE_OPACITY_MINUS, octree.brickOpacityMinus.id());
        bindDirectionalImage(call, volume, GL_READ_WRITE);
        listDispatch_.dispatch(call, volume, kBorderCountSlot + unsigned(level), kBarrier, 1);  // a group per node
        shareSamples(octree, volume, level);
    }
    gl::checkErrors("filtering radiance up the octree by direction");
}

void RadianceFilter::shareSamples(const Octree& octree, RadianceVolume& volume, int level) {
    gl::ComputeCall call = over(share_, octree, volume, level);
    bindDirectionalImage(call, volume, GL_READ_WRITE);
    listDispatch_.dispatch(call, volume, kBorderCountSlot + unsigned(level), kBarrier);
}

}  // namespace vct
