#include "viewer/input_script.hpp"

#include <cmath>
#include <fstream>
#include <sstream>
#include <utility>

#include "core/error.hpp"
#include "core/image.hpp"
#include "viewer/key_bindings.hpp"

namespace vct::viewer {
namespace {

constexpr long kMaxFrames = 10'000'000;  // a typo such as "wait 1e9" is an error, not a hang

std::vector<std::string> words(const std::string& line) {
    std::istringstream stream(line);
    std::vector<std::string> out;
    for (std::string word; stream >> word;) out.push_back(word);
    return out;
}

}  // namespace

InputScript InputScript::load(const std::filesystem::path& path) {
    std::ifstream file(path);
    if (!file) fail("cannot read the script '", path.string(), "'; check the path");
    std::stringstream text;
    text << file.rdbuf();
    return parse(text.str(), path.string());
}

InputScript InputScript::parse(const std::string& text, const std::string& sourceName) {
    InputScript script;
    FrameInput pending;  // input waiting for the next rendered frame
    std::istringstream lines(text);
    std::string line;
    int lineNumber = 0;
    bool quit = false;

    auto where = [&] { return concat("script ", sourceName, " line ", lineNumber, ": "); };
    auto count = [&](const std::string& word, const char* what) {
        char* end = nullptr;
        const long n = std::strtol(word.c_str(), &end, 10);
        if (!end || *end || n < 1 || n > kMaxFrames)
            fail(where(), what, " must be a whole number of frames in 1..", kMaxFrames, ", not '", word, "'");
        return n;
    };
    auto number = [&](const std::string& word, const char* what) {
        char* end = nullptr;
        const double v = std::strtod(word.c_str(), &end);
        if (!end || *end || !std::isfinite(v)) fail(where(), what, " must be a number, not '", word, "'");
        return v;
    };
    auto key = [&](const std::string& word) {
        const auto chord = parseKeyChord(word);
        if (!chord) fail(where(), "unknown key '", word, "' (e.g. G, Shift+V, F1, Home, Left, [, 3)");
        return *chord;
    };
    auto expectWords = [&](const std::vector<std::string>& w, std::size_t n, const char* usage) {
        if (w.size() != n) fail(where(), "expected '", usage, "'");
    };
    auto emit = [&](FrameInput frame) {
        script.frames_.push_back(std::move(frame));
        if (script.frames_.size() > std::size_t(kMaxFrames)) fail(where(), "the script is longer than ", kMaxFrames, " frames");
    };

    while (!quit && std::getline(lines, line)) {
        ++lineNumber;
        if (const auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
        const auto w = words(line);
        if (w.empty()) continue;
        const std::string& command = w[0];
        if (command == "wait") {
            expectWords(w, 2, "wait FRAMES");
            const long n = count(w[1], "wait");
            emit(std::exchange(pending, {}));
            for (long i = 1; i < n; ++i) emit({});
        } else if (command == "key") {
            expectWords(w, 2, "key NAME");
            pending.presses.push_back(key(w[1]));
        } else if (command == "hold") {
            expectWords(w, 3, "hold NAME FRAMES");
            const KeyChord chord = key(w[1]);
            const long n = count(w[2], "hold");
            for (long i = 0; i < n; ++i) {
                FrameInput frame = i == 0 ? std::exchange(pending, {}) : FrameInput{};
                frame.held.push_back(chord.key);
                emit(std::move(frame));
            }
        } else if (command == "mouse") {
            if (w.size() != 4 || w[1] != "drag") fail(where(), "expected 'mouse drag DX DY'");
            pending.dragX += number(w[2], "DX");
            pending.dragY += number(w[3], "DY");
        } else if (command == "scroll") {
            expectWords(w, 2, "scroll NOTCHES");
            pending.scroll += number(w[1], "NOTCHES");
        } else if (command == "resize") {
            expectWords(w, 3, "resize WIDTH HEIGHT");
            pending.resizeWidth = int(count(w[1], "WIDTH"));
            pending.resizeHeight = int(count(w[2], "HEIGHT"));
            if (pending.resizeWidth > kMaxImageSide || pending.resizeHeight > kMaxImageSide)
                fail(where(), "the window size must be within 1..", kMaxImageSide);
        } else if (command == "screenshot") {
            // The rest of the line is the path, so that it may contain spaces.
            const auto start = line.find_first_not_of(" \t", line.find("screenshot") + 10);
            std::string path = start == std::string::npos ? "" : line.substr(start);
            while (!path.empty() && std::isspace(static_cast<unsigned char>(path.back()))) path.pop_back();
            if (path.empty()) fail(where(), "expected 'screenshot PATH'");
            try {
                ensureWritable(path);
            } catch (const Error& e) {
                fail(where(), e.what());
            }
            pending.screenshots.push_back(path);
            emit(std::exchange(pending, {}));
        } else if (command == "quit") {
            expectWords(w, 1, "quit");
            quit = true;
        } else {
            fail(where(), "unknown command '", command,
                 "'; use wait, key, hold, mouse drag, scroll, resize, screenshot or quit");
        }
    }
    if (!pending.empty()) emit(std::move(pending));
    if (script.frames_.empty()) script.frames_.push_back({});  // at least one frame, so the window is seen
    script.frames_.back().quit = true;
    return script;
}

const FrameInput& InputScript::frame(std::uint64_t index) const {
    static const FrameInput none;
    return index < frames_.size() ? frames_[index] : none;
}

}  // namespace vct::viewer
