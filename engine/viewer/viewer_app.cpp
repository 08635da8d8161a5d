#include "viewer/viewer_app.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>

#include "core/error.hpp"
#include "core/image.hpp"
#include "core/log.hpp"
#include "gl/context.hpp"
#include "viewer/camera_controller.hpp"
#include "viewer/frame_stats.hpp"
#include "viewer/imgui_layer.hpp"
#include "viewer/input_script.hpp"
#include "viewer/key_bindings.hpp"
#include "viewer/light_control.hpp"
#include "viewer/live_input.hpp"
#include "viewer/presenter.hpp"
#include "viewer/ui_panel.hpp"
#include "viewer/viewer_state.hpp"

namespace vct::viewer {
namespace {

constexpr double kScriptFrameSeconds = 1.0 / 60.0;  // scripts move by frames, not by wall time
constexpr double kSunDegreesPerSecond = 45.0;
constexpr double kIdleSeconds = 1.0 / 30.0;  // frame interval while no pass has anything to do
#ifdef NDEBUG
constexpr bool kDebugBuild = false;
#else
constexpr bool kDebugBuild = true;
#endif

using Clock = std::chrono::steady_clock;

class ViewerApp {
public:
    ViewerApp(const Scene& scene, const Camera& startCamera, const RenderSettings& settings,
              const ViewerOptions& options, std::optional<InputScript> script)
        : scene_(scene),
          startCamera_(startCamera),
          options_(options),
          script_(std::move(script)),
          context_(openWindow(scene, options)),
          window_(context_->window()),
          input_(window_),
          imgui_(window_, script_.has_value()),
          controller_(startCamera, glm::length(scene.worldBounds.size())) {
        glfwSwapInterval(script_ ? 0 : 1);  // a script runs as fast as it can
        state_.settings = settings;
        state_.lights = scene.lights;
        state_.renderScale = options.renderScale;
        int width = 0, height = 0;
        glfwGetFramebufferSize(window_, &width, &height);
        const auto [w, h] = renderSize(std::max(width, 1), std::max(height, 1));
        state_.settings.width = w;
        state_.settings.height = h;
        renderer_ = std::make_unique<Renderer>(scene_, state_.settings);
        presenter_ = std::make_unique<Presenter>();
        good_ = state_.settings;
    }

    ~ViewerApp() {
        // GL objects go before the context (members are destroyed in reverse order anyway; the
        // renderer and presenter are explicit so that the order is visible here).
        presenter_.reset();
        renderer_.reset();
    }

    void run() {
        auto last = Clock::now();
        auto lastTitle = last;
        std::uint64_t frame = 0;
        for (bool quit = false; !quit;) {
            int width = 0, height = 0;
            glfwGetFramebufferSize(window_, &width, &height);
            const bool minimised = width == 0 || height == 0 || glfwGetWindowAttrib(window_, GLFW_ICONIFIED);
            if (minimised && !script_)
                glfwWaitEventsTimeout(0.1);  // nothing to show: sleep instead of spinning
            else if (idle_ && !script_)
                glfwWaitEventsTimeout(kIdleSeconds);  // nothing changed: wake on input, or to refresh the panel
            else
                glfwPollEvents();
            if (glfwWindowShouldClose(window_)) break;

            const auto now = Clock::now();
            const double seconds = std::min(std::chrono::duration<double>(now - last).count(), 0.25);
            last = now;

            FrameInput live = input_.collect();  // drained even while a script plays
            if (minimised && !script_) continue;  // 0 × 0 framebuffer: no rendering at all
            const FrameInput& input = script_ ? script_->frame(frame) : live;
            quit = handle(input, script_ ? kScriptFrameSeconds : seconds);
            if (input.resizeWidth > 0) glfwSetWindowSize(window_, input.resizeWidth, input.resizeHeight);
            glfwGetFramebufferSize(window_, &width, &height);
            if (width > 0 && height > 0) {
                renderAndPresent(width, height);
                for (const auto& path : input.screenshots) screenshot(path, width, height, true);
                if (state_.screenshotRequested) screenshot(nextScreenshotPath(), width, height, false);
                glfwSwapBuffers(window_);
                if (kDebugBuild || script_) gl::checkErrors("presenting a viewer frame");
            }
            state_.screenshotRequested = false;
            stats_.addFrameTime(seconds * 1000.0);
            ++frame;
            if (script_ && script_->finished(frame)) quit = true;
            if (now - lastTitle > std::chrono::milliseconds(500)) {
                lastTitle = now;
                updateTitle();
            }
        }
        glFinish();
        gl::checkErrors("closing the viewer");
        logInfo(concat("viewer closed after ", frame, " frames"));
    }

private:
    static std::unique_ptr<gl::Context> openWindow(const Scene& scene, const ViewerOptions& options) {
        gl::ContextOptions context;
        context.visibleWindow = true;
        context.windowWidth = options.windowWidth;
        context.windowHeight = options.windowHeight;
        context.windowTitle = "vct view: " + scene.name;
        return gl::createContext(gl::Backend::GLFW, context);
    }

    std::pair<int, int> renderSize(int windowWidth, int windowHeight) const {
        return {std::max(1, int(std::lround(windowWidth * double(state_.renderScale)))),
                std::max(1, int(std::lround(windowHeight * double(state_.renderScale))))};
    }

    // Applies one frame of input; returns true when the viewer should quit after this frame.
    bool handle(const FrameInput& input, double seconds) {
        bool quit = input.quit;
        for (const KeyChord& chord : input.presses) quit |= apply(actionFor(chord));

        glm::dvec3 move(0.0);
        if (input.isHeld(HeldKeys::kForward)) move.z += 1.0;
        if (input.isHeld(HeldKeys::kBack)) move.z -= 1.0;
        if (input.isHeld(HeldKeys::kRight)) move.x += 1.0;
        if (input.isHeld(HeldKeys::kLeft)) move.x -= 1.0;
        if (input.isHeld(HeldKeys::kUp)) move.y += 1.0;
        if (input.isHeld(HeldKeys::kDown)) move.y -= 1.0;
        controller_.move(move, seconds);
        controller_.look(input.dragX, input.dragY);
        if (input.scroll != 0.0) controller_.scaleSpeed(input.scroll);

        double azimuth = 0.0, elevation = 0.0;
        if (input.isHeld(HeldKeys::kSunLeft)) azimuth -= 1.0;
        if (input.isHeld(HeldKeys::kSunRight)) azimuth += 1.0;
        if (input.isHeld(HeldKeys::kSunUp)) elevation += 1.0;
        if (input.isHeld(HeldKeys::kSunDown)) elevation -= 1.0;
        const int light = steeredLight(state_.lights);
        if ((azimuth != 0.0 || elevation != 0.0) && light >= 0) {
            const double step = kSunDegreesPerSecond * seconds;
            rotateLight(state_.lights[std::size_t(light)], azimuth * step, elevation * step);
            lightsDirty_ = true;
        }
        return quit;
    }

    bool apply(Action action) {
        RenderSettings& s = state_.settings;
        auto setAov = [&](Aov aov) {
            s.display.aov = aov;
            s.view = ViewMode::Lit;
            status(concat("output: ", aovName(aov)));
        };
        const int shownLevel = s.voxelViewLevel ? s.voxelViewLevel : s.voxelLevels;
        switch (action) {
            case Action::None: return false;
            case Action::ToggleGi: s.gi = !s.gi; status(s.gi ? "GI on" : "GI off"); break;
            case Action::ToggleBricks: s.bricks = !s.bricks; status(s.bricks ? "filtered bricks" : "unfiltered (nearest sample, raw node values)"); break;
            case Action::TogglePhotons: s.photons = !s.photons; status(s.photons ? "photons on" : "photons off"); break;
            case Action::NextBounceCount:
                s.bounces = s.bounces % kMaxBounces + 1;
                status(std::to_string(s.bounces) + (s.bounces == 1 ? " bounce" : " bounces"));
                break;
            case Action::ToggleGiResolution:
                s.giResolution = nextGiResolution(s.giResolution);
                status(std::string("GI resolution ") + giResolutionName(s.giResolution));
                break;
            case Action::ToggleNarrowCones:
                s.cones.rays = s.cones.rays > 0 ? 0 : kDefaultNarrowCones;
                status(s.cones.rays > 0 ? concat(s.cones.rays, " narrow cones per pixel") : concat(s.cones.cones, "-cone set"));
                break;
            case Action::ToggleVoxelView:
                s.view = s.view == ViewMode::Voxels ? ViewMode::Lit : ViewMode::Voxels;
                status(s.view == ViewMode::Voxels ? concat("voxel view, level ", shownLevel) : std::string("lit view"));
                break;
            case Action::ToggleRadianceView:
                s.view = s.view == ViewMode::Radiance ? ViewMode::Lit : ViewMode::Radiance;
                status(s.view == ViewMode::Radiance ? concat("radiance view, level ", shownLevel) : std::string("lit view"));
                break;
            case Action::CoarserLevel:
            case Action::FinerLevel: {
                const int level = std::clamp(shownLevel + (action == Action::FinerLevel ? 1 : -1), 1, s.voxelLevels);
                s.voxelViewLevel = level == s.voxelLevels ? 0 : level;
                status(concat("octree level ", level, " of ", s.voxelLevels));
                break;
            }
            case Action::AovFinal: setAov(Aov::Final); break;
            case Action::AovDirect: setAov(Aov::Direct); break;
            case Action::AovIndirect: setAov(Aov::Indirect); break;
            case Action::AovAo: setAov(Aov::Ao); break;
            case Action::AovAlbedo: setAov(Aov::Albedo); break;
            case Action::AovNormal: setAov(Aov::Normal); break;
            case Action::ResetCamera: controller_.setCamera(startCamera_); status("start camera"); return false;
            case Action::TogglePanel: state_.panelVisible = !state_.panelVisible; return false;
            case Action::Screenshot: state_.screenshotRequested = true; return false;
            case Action::Quit: return true;
        }
        settingsDirty_ = true;
        return false;
    }

    void status(const std::string& message) { state_.status = message; }

    void renderAndPresent(int width, int height) {
        const auto [w, h] = renderSize(width, height);
        if (w != state_.settings.width || h != state_.settings.height) {
            state_.settings.width = w;
            state_.settings.height = h;
            settingsDirty_ = true;
        }
        const bool changed = settingsDirty_;
        if (settingsDirty_) {
            settingsDirty_ = false;
            try {
                renderer_->setSettings(state_.settings);
            } catch (const Error& e) {
                reject(e);
            }
        }
        const bool lightsChanged = lightsDirty_;
        if (lightsDirty_) {
            lightsDirty_ = false;
            renderer_->setLights(state_.lights);
        }
        // Progressive anti-aliasing: a still picture gathers one more jittered sample per frame
        // up to the limit; any change goes back to the pixel centres (sample 0).
        const Camera camera = controller_.camera();
        const bool restart = changed || lightsChanged || lastCamera_ != camera;
        sample_ = restart ? 0 : std::min(sample_ + 1, std::max(state_.accumulateSamples, 1) - 1);
        lastCamera_ = camera;
        try {
            renderer_->renderFrame(camera, sample_);
            good_ = renderer_->settings();
        } catch (const Error& e) {
            if (!changed) throw;  // not caused by an edit: nothing to go back to
            reject(e);
            sample_ = 0;
            renderer_->renderFrame(camera, sample_);
        }
        while (auto timings = renderer_->timer().poll()) stats_.addTimings(*timings);
        const auto& passes = renderer_->lastFrame();
        idle_ = std::none_of(passes.begin(), passes.end(), [](const PassRun& pass) { return pass.ran; });

        const RenderSettings& applied = renderer_->settings();
        presenter_->present(renderer_->outputTexture(), applied.width, applied.height, width, height);

        imgui_.beginFrame();
        if (state_.panelVisible) {
            const PanelEdits edits =
                panel_.draw(state_, {scene_, *renderer_, stats_, controller_, context_->info(), width, height, idle_});
            settingsDirty_ |= edits.settings;
            lightsDirty_ |= edits.lights;
            if (state_.cameraPreset >= 0) {
                controller_.setCamera(scene_.cameras.at(std::size_t(state_.cameraPreset)));
                status("camera " + scene_.cameras[std::size_t(state_.cameraPreset)].name);
                state_.cameraPreset = -1;
            }
        }
        imgui_.endFrame(true);
        input_.setUiCapture(imgui_.wantsMouse(), imgui_.wantsKeyboard());
    }

    // An edit the renderer refused (out of range, out of GPU memory): back to what worked.
    void reject(const Error& e) {
        status(concat("not applied: ", e.what()));
        logWarn(concat("viewer: setting not applied: ", e.what()));
        const float scale = state_.renderScale;
        state_.settings = good_;
        state_.renderScale = scale;
        renderer_->setSettings(good_);
    }

    std::filesystem::path nextScreenshotPath() const {
        for (int i = 1;; ++i) {
            char name[32];
            std::snprintf(name, sizeof name, "vct_view_%04d.png", i);
            const auto path = options_.screenshotDir / name;
            if (!std::filesystem::exists(path)) return path;
        }
    }

    void screenshot(const std::filesystem::path& path, int width, int height, bool fromScript) {
        try {
            writePng(path, Presenter::readWindow(width, height));
        } catch (const Error& e) {
            if (fromScript) throw;
            status(concat("screenshot failed: ", e.what()));
            logWarn(concat("viewer: screenshot failed: ", e.what()));
            return;
        }
        std::printf("screenshot %s (%dx%d)\n", path.string().c_str(), width, height);
        std::fflush(stdout);
        if (!fromScript) status("wrote " + path.string());
    }

    void updateTitle() {
        char title[256];
        const double ms = stats_.meanFrameMs();
        std::snprintf(title, sizeof title, "vct view: %s  %.1f ms (%.1f fps)%s", scene_.name.c_str(), ms,
                      ms > 0 ? 1000.0 / ms : 0.0, state_.settings.gi ? "" : "  [GI off]");
        glfwSetWindowTitle(window_, title);
    }

    const Scene& scene_;
    const Camera startCamera_;
    const ViewerOptions options_;
    std::optional<InputScript> script_;
    std::unique_ptr<gl::Context> context_;
    GLFWwindow* window_;
    LiveInput input_;
    ImGuiLayer imgui_;
    CameraController controller_;
    ViewerState state_;
    RenderSettings good_;  // the last settings a frame rendered with
    bool settingsDirty_ = false, lightsDirty_ = false;
    bool idle_ = false;  // the last frame ran no pass (the picture cannot have changed)
    std::optional<Camera> lastCamera_;
    int sample_ = 0;     // the sample of the last frame (render/pixel_samples.hpp)
    std::unique_ptr<Renderer> renderer_;
    std::unique_ptr<Presenter> presenter_;
    FrameStats stats_;
    UiPanel panel_;
};

}  // namespace

void checkViewerOptions(const ViewerOptions& options) {
    if (!(options.renderScale >= 0.1f && options.renderScale <= 1.0f))
        fail("--render-scale ", options.renderScale, " is out of range; use 0.1..1");
    validateImageSize(options.windowWidth, options.windowHeight, "window size");
    auto set = [](const char* name) {
        const char* value = std::getenv(name);
        return value && *value;
    };
    if (!set("DISPLAY") && !set("WAYLAND_DISPLAY"))
        fail("vct view needs a display and neither DISPLAY nor WAYLAND_DISPLAY is set; on a machine without "
             "one run it under Xvfb (Xvfb :99 & DISPLAY=:99 vct view ...), or render images with vct render");
}

void runViewer(const Scene& scene, const Camera& startCamera, const RenderSettings& settings,
               const ViewerOptions& options, std::optional<InputScript> script) {
    checkViewerOptions(options);
    ViewerApp app(scene, startCamera, settings, options, std::move(script));
    app.run();
}

}  // namespace vct::viewer
