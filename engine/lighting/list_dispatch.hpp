#pragma once
// Dispatching a compute pass over a list whose length only the GPU knows (touched or border
// nodes): a one-thread pass turns the count into dispatch arguments, then
// glDispatchComputeIndirect runs the real pass. No read-back, no stall.
#include "gl/objects.hpp"
#include "lighting/radiance_volume.hpp"

namespace vct {

constexpr unsigned kTouchedCountSlot = 0;   // + level
constexpr unsigned kBorderCountSlot = 12;   // + level

class ListDispatch {
public:
    ListDispatch();
    // Dispatches the currently bound program over listCounts[countSlot] items in groups of 64.
    void dispatch(const RadianceVolume& volume, unsigned countSlot);

private:
    gl::Program args_;
};

void bindRadianceVolume(const RadianceVolume& volume);

}  // namespace vct
