#include "viewer/key_bindings.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cctype>
#include <string_view>
#include <vector>

namespace vct::viewer {
namespace {

struct Binding {
    KeyChord chord;
    Action action;
};

const Binding kBindings[] = {
    {{GLFW_KEY_G, 0}, Action::ToggleGi},
    {{GLFW_KEY_B, 0}, Action::ToggleBricks},
    {{GLFW_KEY_P, 0}, Action::TogglePhotons},
    {{GLFW_KEY_N, 0}, Action::NextBounceCount},
    {{GLFW_KEY_H, 0}, Action::ToggleGiResolution},
    {{GLFW_KEY_C, 0}, Action::ToggleNarrowCones},
    {{GLFW_KEY_V, 0}, Action::ToggleVoxelView},
    {{GLFW_KEY_V, GLFW_MOD_SHIFT}, Action::ToggleRadianceView},
    {{GLFW_KEY_LEFT_BRACKET, 0}, Action::CoarserLevel},
    {{GLFW_KEY_RIGHT_BRACKET, 0}, Action::FinerLevel},
    {{GLFW_KEY_1, 0}, Action::AovFinal},
    {{GLFW_KEY_2, 0}, Action::AovDirect},
    {{GLFW_KEY_3, 0}, Action::AovIndirect},
    {{GLFW_KEY_4, 0}, Action::AovAo},
    {{GLFW_KEY_5, 0}, Action::AovAlbedo},
    {{GLFW_KEY_6, 0}, Action::AovNormal},
    {{GLFW_KEY_HOME, 0}, Action::ResetCamera},
    {{GLFW_KEY_F1, 0}, Action::TogglePanel},
    {{GLFW_KEY_F12, 0}, Action::Screenshot},
    {{GLFW_KEY_ESCAPE, 0}, Action::Quit},
};

struct NamedKey {
    std::string_view name;
    int key;
};

const NamedKey kNamedKeys[] = {
    {"esc", GLFW_KEY_ESCAPE},      {"escape", GLFW_KEY_ESCAPE},  {"home", GLFW_KEY_HOME},
    {"end", GLFW_KEY_END},         {"left", GLFW_KEY_LEFT},      {"right", GLFW_KEY_RIGHT},
    {"up", GLFW_KEY_UP},           {"down", GLFW_KEY_DOWN},      {"space", GLFW_KEY_SPACE},
    {"enter", GLFW_KEY_ENTER},     {"tab", GLFW_KEY_TAB},        {"[", GLFW_KEY_LEFT_BRACKET},
    {"]", GLFW_KEY_RIGHT_BRACKET}, {"leftbracket", GLFW_KEY_LEFT_BRACKET}, {"rightbracket", GLFW_KEY_RIGHT_BRACKET},
    {"pageup", GLFW_KEY_PAGE_UP},  {"pagedown", GLFW_KEY_PAGE_DOWN},
};

std::string lower(std::string_view text) {
    std::string out(text);
    for (char& c : out) c = char(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

std::optional<int> parseKey(const std::string& name) {
    if (name.size() == 1) {
        const char c = name[0];
        if (c >= 'a' && c <= 'z') return GLFW_KEY_A + (c - 'a');
        if (c >= '0' && c <= '9') return GLFW_KEY_0 + (c - '0');
    }
    if (name.size() >= 2 && name[0] == 'f' && std::all_of(name.begin() + 1, name.end(), ::isdigit)) {
        const int n = std::stoi(name.substr(1));
        if (n >= 1 && n <= 25) return GLFW_KEY_F1 + (n - 1);
    }
    for (const auto& named : kNamedKeys)
        if (named.name == name) return named.key;
    return std::nullopt;
}

std::string keyName(int key) {
    if (key >= GLFW_KEY_A && key <= GLFW_KEY_Z) return std::string(1, char('A' + (key - GLFW_KEY_A)));
    if (key >= GLFW_KEY_0 && key <= GLFW_KEY_9) return std::string(1, char('0' + (key - GLFW_KEY_0)));
    if (key >= GLFW_KEY_F1 && key <= GLFW_KEY_F25) return std::string("F").append(std::to_string(key - GLFW_KEY_F1 + 1));
    switch (key) {
        case GLFW_KEY_ESCAPE: return "Esc";
        case GLFW_KEY_HOME: return "Home";
        case GLFW_KEY_END: return "End";
        case GLFW_KEY_LEFT: return "Left";
        case GLFW_KEY_RIGHT: return "Right";
        case GLFW_KEY_UP: return "Up";
        case GLFW_KEY_DOWN: return "Down";
        case GLFW_KEY_SPACE: return "Space";
        case GLFW_KEY_ENTER: return "Enter";
        case GLFW_KEY_TAB: return "Tab";
        case GLFW_KEY_LEFT_BRACKET: return "[";
        case GLFW_KEY_RIGHT_BRACKET: return "]";
        case GLFW_KEY_PAGE_UP: return "PageUp";
        case GLFW_KEY_PAGE_DOWN: return "PageDown";
    }
    return std::string("key").append(std::to_string(key));
}

}  // namespace

Action actionFor(const KeyChord& chord) {
    // Only Shift and Ctrl distinguish chords; Caps/Num Lock never change what a key does.
    const KeyChord normalized{chord.key, chord.mods & (GLFW_MOD_SHIFT | GLFW_MOD_CONTROL)};
    for (const auto& binding : kBindings)
        if (binding.chord == normalized) return binding.action;
    return Action::None;
}

std::optional<KeyChord> parseKeyChord(const std::string& text) {
    KeyChord chord;
    std::string rest = lower(text);
    for (;;) {
        const auto plus = rest.find('+');
        if (plus == std::string::npos || plus == 0 || plus + 1 == rest.size()) break;
        const std::string modifier = rest.substr(0, plus);
        if (modifier == "shift")
            chord.mods |= GLFW_MOD_SHIFT;
        else if (modifier == "ctrl" || modifier == "control")
            chord.mods |= GLFW_MOD_CONTROL;
        else if (modifier == "alt")
            chord.mods |= GLFW_MOD_ALT;
        else
            return std::nullopt;
        rest = rest.substr(plus + 1);
    }
    const auto key = parseKey(rest);
    if (!key) return std::nullopt;
    chord.key = *key;
    return chord;
}

std::string keyChordName(const KeyChord& chord) {
    std::string name;
    if (chord.mods & GLFW_MOD_CONTROL) name += "Ctrl+";
    if (chord.mods & GLFW_MOD_ALT) name += "Alt+";
    if (chord.mods & GLFW_MOD_SHIFT) name += "Shift+";
    return name + keyName(chord.key);
}

const std::string& keyHelp() {
    static const std::string help =
        "Keys:\n"
        "  W A S D      move forward / left / back / right (R / F: up / down)\n"
        "  left drag    look around;  mouse wheel: move speed x1.25 per notch\n"
        "  Home         back to the start camera (presets: in the panel)\n"
        "  G            global illumination on/off\n"
        "  B            filtered bricks / raw octree node values\n"
        "  P            photon injection on/off\n"
        "  N            light bounces: 1, 2, ... 8, then 1 (one bounce is the default)\n"
        "  H            GI resolution: cones at every pixel / at one pixel of each 2x2 block\n"
        "  C            4 narrow cones per pixel (the default: closer to the path tracer) / the cone set (faster)\n"
        "  V            voxel view (octree albedo) on/off;  Shift+V: radiance view\n"
        "  [ ]          voxel views: coarser / finer octree level\n"
        "  1..6         output: final, direct, indirect, ao, albedo, normal\n"
        "  arrow keys   rotate the sun (left/right: azimuth, up/down: elevation)\n"
        "  F1           panel on/off;  F12: screenshot (PNG, path printed);  Esc: quit\n";
    return help;
}

const std::string& keyHelpLine() {
    static const std::string line =
        "WASD/RF move, drag look, wheel speed, Home reset | G gi, B bricks, P photons, N bounces, H GI res, C narrow cones, V voxels, Shift+V radiance, "
        "[ ] level | 1-6 final/direct/indirect/ao/albedo/normal | arrows sun | F1 panel, F12 screenshot, Esc quit";
    return line;
}

}  // namespace vct::viewer
