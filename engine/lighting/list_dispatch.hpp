#pragma once
// Dispatching a compute pass over a list whose length only the GPU knows (touched or border
// nodes): a one-thread pass turns the count into dispatch arguments, then
// glDispatchComputeIndirect runs the real pass. No read-back, no stall.
#include "gl/compute.hpp"
#include "lighting/radiance_volume.hpp"

namespace vct {

constexpr unsigned kTouchedCountSlot = 0;                // + level
constexpr unsigned kBorderCountSlot = gl::BORDER_COUNT_SLOT;  // + level

class ListDispatch {
public:
    ListDispatch();
    // Dispatches `call`'s program over listCounts[countSlot] items, itemsPerGroup to a work group
    // (64: one per invocation of a 64-wide group; 1: a whole group per item).
    void dispatch(const gl::ComputeCall& call, const RadianceVolume& volume, unsigned countSlot, GLbitfield barriers,
                  unsigned itemsPerGroup = 64);
    // The same for a count kept elsewhere: uints `counts`[countSlot], the dispatch arguments
    // written to `args` at argsSlot (three uints each).
    void dispatch(const gl::ComputeCall& call, const gl::Buffer& counts, unsigned countSlot, const gl::Buffer& args,
                  unsigned argsSlot, GLbitfield barriers, unsigned itemsPerGroup = 64);

private:
    gl::Program args_;
};

// Binds the radiance volume's buffers at their shader interface slots.
void bindRadianceVolume(const RadianceVolume& volume);

}  // namespace vct
