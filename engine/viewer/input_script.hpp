#pragma once
// `vct view --script FILE`: a timeline of input replayed frame by frame, for tests and figures.
// It is driven by frame count, never by wall time, and movement then uses a fixed time step,
// so the same script gives the same frames on any machine.
//
// One command per line; '#' starts a comment; blank lines are ignored.
//   wait N              render N frames (N ≥ 1); queued input goes to the first of them
//   key NAME            press NAME (e.g. G, Shift+V, F1, Home, Left, [, 3) in the next frame
//   hold NAME N         hold NAME down for the next N frames (movement keys, arrow keys)
//   mouse drag DX DY    drag with the left button by DX, DY pixels in the next frame (look)
//   scroll N            turn the mouse wheel by N notches in the next frame (move speed)
//   resize W H          ask for a W × H window from the next frame on
//   screenshot PATH     render one frame (with the queued input) and write the window to PATH
//   quit                leave (the script's end does too)
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "viewer/frame_input.hpp"

namespace vct::viewer {

class InputScript {
public:
    // Throws vct::Error naming the file, line and what is wrong.
    static InputScript load(const std::filesystem::path& path);
    static InputScript parse(const std::string& text, const std::string& sourceName);

    // Input of frame `index` (0 = the first frame the viewer renders); empty after the end.
    const FrameInput& frame(std::uint64_t index) const;
    std::uint64_t frameCount() const { return frames_.size(); }
    // True once every frame of the script has been rendered.
    bool finished(std::uint64_t renderedFrames) const { return renderedFrames >= frames_.size(); }

private:
    std::vector<FrameInput> frames_;
};

}  // namespace vct::viewer
