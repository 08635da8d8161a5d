// `vct view`: the interactive viewer (engine/viewer). Takes the scene, camera and light options
// of `vct render` and its render settings; the window size replaces the image size.
#include <filesystem>

#include "cli/commands.hpp"
#include "cli/render_options.hpp"
#include "cli/scene_options.hpp"
#include "core/error.hpp"
#include "viewer/input_script.hpp"
#include "viewer/key_bindings.hpp"
#include "viewer/viewer_app.hpp"

namespace vct::cli {
namespace {

struct ViewOptions {
    SceneOptions scene;
    RenderSettingsOptions render;
    viewer::ViewerOptions viewer;
    std::string script;
    std::string screenshotDir = ".";
};

void run(const ViewOptions& o) {
    // What the user can get wrong is reported before the (possibly slow) scene load.
    std::optional<viewer::InputScript> script;
    if (!o.script.empty()) script = viewer::InputScript::load(o.script);
    viewer::ViewerOptions options = o.viewer;
    options.screenshotDir = o.screenshotDir;
    if (!std::filesystem::is_directory(options.screenshotDir))
        fail("--screenshot-dir '", o.screenshotDir, "' is not a folder");
    viewer::checkViewerOptions(options);
    renderSettingsFromOptions(o.render, Scene{});  // bad values fail here, before the scene loads

    const Scene scene = loadSceneFromOptions(o.scene);
    const Camera camera = cameraFromOptions(o.scene, scene);
    const RenderSettings settings = renderSettingsFromOptions(o.render, scene);
    viewer::runViewer(scene, camera, settings, options, std::move(script));
}

}  // namespace

Run addViewCommand(CLI::App& app) {
    auto options = std::make_shared<ViewOptions>();
    ViewOptions& o = *options;
    CLI::App* command = app.add_subcommand("view", "interactive viewer: a window with the full pipeline, keys and a panel");
    addSceneOptions(*command, o.scene, true);
    command->add_option("--width", o.viewer.windowWidth, "window width in pixels")->capture_default_str();
    command->add_option("--height", o.viewer.windowHeight, "window height in pixels")->capture_default_str();
    command->add_option("--render-scale", o.viewer.renderScale,
                        "render resolution as a fraction of the window's (0.1..1), scaled up to the window")
        ->capture_default_str();
    command->add_option("--script", o.script,
                        "replay FILE (wait/key/hold/mouse drag/scroll/resize/screenshot/quit, one per line; see "
                        "docs/viewer.md) frame by frame, then exit");
    command->add_option("--screenshot-dir", o.screenshotDir, "folder for F12 screenshots (vct_view_NNNN.png)")
        ->capture_default_str();
    addRenderSettingsOptions(*command, o.render);
    command->footer(viewer::keyHelp());
    return [options] { run(*options); };
}

}  // namespace vct::cli
