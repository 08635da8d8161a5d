#pragma once
// Everything the user (or a script) did during one frame, in one value. The viewer reads only
// this, never GLFW directly, so live input and `--script` replays drive exactly the same code.
#include <string>
#include <vector>

namespace vct::viewer {

// A key and its modifier keys (GLFW_KEY_* and GLFW_MOD_* values).
struct KeyChord {
    int key = 0;
    int mods = 0;
    bool operator==(const KeyChord&) const = default;
};

struct FrameInput {
    std::vector<KeyChord> presses;  // keys pressed this frame (auto-repeat included), in order
    std::vector<int> held;          // keys down during this frame (movement, sun rotation)
    double dragX = 0.0, dragY = 0.0;  // left-button mouse drag this frame, pixels (x right, y down)
    double scroll = 0.0;            // wheel notches this frame (+ = away from the user)
    std::vector<std::string> screenshots;  // PNG paths to write from this frame's window image
    int resizeWidth = 0, resizeHeight = 0; // ask the window system for this window size (0 = no)
    bool quit = false;              // leave after this frame

    bool isHeld(int key) const {
        for (int k : held)
            if (k == key) return true;
        return false;
    }
    bool empty() const {
        return presses.empty() && held.empty() && dragX == 0.0 && dragY == 0.0 && scroll == 0.0 && screenshots.empty() &&
               resizeWidth == 0 && !quit;
    }
};

}  // namespace vct::viewer
