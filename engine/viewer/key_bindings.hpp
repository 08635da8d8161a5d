#pragma once
// The viewer's keyboard map: which key does what, the names keys have in `--script` files, and
// the help text shown by `vct view --help` and in the panel. One table, so the three agree.
#include <optional>
#include <string>

#include "viewer/frame_input.hpp"

namespace vct::viewer {

enum class Action {
    None,
    ToggleGi,            // G
    ToggleBricks,        // B
    TogglePhotons,       // P
    NextBounceCount,     // N       bounces 1, 2, … kMaxBounces, then 1 again
    ToggleGiResolution,  // H       cones at: auto -> every pixel -> 2×2 blocks -> 4×4 blocks -> auto
    ToggleNarrowCones,   // C       narrow cones per traced pixel (`--cone-rays`) <-> the cone set
    ToggleVoxelView,     // V       lit <-> octree albedo
    ToggleRadianceView,  // Shift+V lit <-> octree radiance
    CoarserLevel,        // [       voxel views: one octree level up
    FinerLevel,          // ]       voxel views: one level down
    AovFinal,            // 1
    AovDirect,           // 2
    AovIndirect,         // 3
    AovAo,               // 4
    AovAlbedo,           // 5
    AovNormal,           // 6
    ResetCamera,         // Home
    TogglePanel,         // F1
    Screenshot,          // F12
    Quit,                // Esc
};

// The action of a key press (None for keys without one; movement keys act while held).
Action actionFor(const KeyChord& chord);

// Keys that act while held: movement and sun rotation (GLFW_KEY_*).
struct HeldKeys {
    static constexpr int kForward = 87, kLeft = 65, kBack = 83, kRight = 68, kUp = 82, kDown = 70;  // W A S D R F
    static constexpr int kSunLeft = 263, kSunRight = 262, kSunUp = 265, kSunDown = 264;            // arrow keys
};
inline constexpr int kHeldKeys[] = {HeldKeys::kForward, HeldKeys::kLeft,    HeldKeys::kBack,
                                    HeldKeys::kRight,   HeldKeys::kUp,      HeldKeys::kDown,
                                    HeldKeys::kSunLeft, HeldKeys::kSunRight, HeldKeys::kSunUp,
                                    HeldKeys::kSunDown};

// "G", "g", "Shift+V", "F1", "F12", "Esc", "Home", "Left", "[", "]", "1", "Space", "Ctrl+Shift+X"…
// (case-insensitive). nullopt for a name that is no key.
std::optional<KeyChord> parseKeyChord(const std::string& name);
std::string keyChordName(const KeyChord& chord);

// Every key and what it does, one per line ("  G        global illumination on/off").
const std::string& keyHelp();
// The same on one line, for the panel's help line.
const std::string& keyHelpLine();

}  // namespace vct::viewer
