#include "viewer/ui_panel.hpp"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <iterator>

#include "viewer/key_bindings.hpp"
#include "viewer/light_control.hpp"

namespace vct::viewer {
namespace {

constexpr float kPanelWidth = 470.0f;

float dequeValue(void* data, int index) { return (*static_cast<const std::deque<float>*>(data))[std::size_t(index)]; }

void plot(const char* label, const std::deque<float>& history, const char* overlay, float height) {
    if (history.empty()) return;
    const float top = std::max(1e-3f, *std::max_element(history.begin(), history.end()) * 1.1f);
    ImGui::PlotLines(label, dequeValue, const_cast<std::deque<float>*>(&history), int(history.size()), 0, overlay, 0.0f,
                     top, ImVec2(ImGui::GetContentRegionAvail().x, height));
}

std::string megabytes(std::size_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f MiB", double(bytes) / (1024.0 * 1024.0));
    return text;
}

void frameSection(const PanelInputs& in) {
    const auto& stats = in.stats;
    const double ms = stats.meanFrameMs();
    ImGui::Text("frame %.1f ms (%.1f fps)%s   window %dx%d, render %dx%d", ms, ms > 0 ? 1000.0 / ms : 0.0,
                in.idle ? " idle" : "", in.windowWidth, in.windowHeight, in.renderer.settings().width,
                in.renderer.settings().height);
    ImGui::TextDisabled("%s", in.context.renderer.c_str());
    ImGui::Text("samples per pixel %d", in.renderer.samplesInOutput());
    char overlay[64];
    const float gpu = stats.gpuHistory().empty() ? 0.0f : stats.gpuHistory().back();
    std::snprintf(overlay, sizeof overlay, "GPU %.2f ms (last %zu frames)", gpu, stats.gpuHistory().size());
    plot("##gpu", stats.gpuHistory(), overlay, 48.0f);
}

void passesSection(const PanelInputs& in) {
    if (!ImGui::CollapsingHeader("Passes", ImGuiTreeNodeFlags_DefaultOpen)) return;
    // Ran or skipped (and why) is this frame's; GPU timings arrive a frame or more late, and a
    // skipped pass shows, dimmed, what it cost when it last ran.
    const auto& latest = in.stats.latest();
    const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingFixedFit;
    if (ImGui::BeginTable("passes", 4, flags)) {
        ImGui::TableSetupColumn("pass");
        ImGui::TableSetupColumn("GPU ms");
        ImGui::TableSetupColumn("CPU ms");
        ImGui::TableSetupColumn("ran (green) / skipped: why", ImGuiTableColumnFlags_WidthStretch);
        ImGui::TableHeadersRow();
        for (const auto& run : in.renderer.lastFrame()) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(run.name.c_str());
            const auto measured = in.stats.lastRun(run.name);
            const bool current = measured && latest && measured->frame == latest->frame;
            ImGui::TableNextColumn();
            if (measured) (current ? ImGui::Text : ImGui::TextDisabled)("%6.2f", measured->gpuMs);
            ImGui::TableNextColumn();
            if (measured) (current ? ImGui::Text : ImGui::TextDisabled)("%6.2f", measured->cpuMs);
            ImGui::TableNextColumn();
            ImGui::PushTextWrapPos(0.0f);
            if (run.ran)
                ImGui::TextColored(ImVec4(0.5f, 0.9f, 0.5f, 1.0f), "ran%s%s", run.reason.empty() ? "" : ": ",
                                   run.reason.c_str());
            else
                ImGui::TextDisabled("%s", run.reason.empty() ? "skipped" : run.reason.c_str());
            ImGui::PopTextWrapPos();
        }
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted("total");
        ImGui::TableNextColumn();
        if (latest) ImGui::Text("%6.2f", latest->totalGpuMs);
        ImGui::TableNextColumn();
        if (latest) ImGui::Text("%6.2f", latest->totalCpuMs);
        ImGui::TableNextColumn();
        if (latest) ImGui::TextDisabled("timed frame %llu", static_cast<unsigned long long>(latest->frame));
        ImGui::EndTable();
    }
    if (ImGui::TreeNode("GPU ms per pass, last frames")) {
        for (const auto& name : in.stats.passNames()) {
            const auto& history = in.stats.passHistory(name);
            char overlay[96];
            std::snprintf(overlay, sizeof overlay, "%s %.2f ms", name.c_str(), history.empty() ? 0.0f : history.back());
            plot(("##" + name).c_str(), history, overlay, 28.0f);
        }
        ImGui::TreePop();
    }
}

void memorySection(const PanelInputs& in) {
    if (!ImGui::CollapsingHeader("GPU memory")) return;
    std::size_t total = 0;
    if (ImGui::BeginTable("memory", 2, ImGuiTableFlags_RowBg)) {
        ImGui::TableSetupColumn("pool", ImGuiTableColumnFlags_WidthStretch);
        ImGui::TableSetupColumn("size", ImGuiTableColumnFlags_WidthFixed, ImGui::CalcTextSize("0000.0 MiB").x);
        for (const auto& pool : in.renderer.memory()) {
            total += pool.bytes;
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::PushTextWrapPos(0.0f);
            ImGui::TextUnformatted(pool.name.c_str());
            ImGui::PopTextWrapPos();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(megabytes(pool.bytes).c_str());
        }
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted("total");
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(megabytes(total).c_str());
        ImGui::EndTable();
    }
}

void cameraSection(ViewerState& state, const PanelInputs& in) {
    if (!ImGui::CollapsingHeader("Camera")) return;
    const Camera& camera = in.camera.camera();
    if (ImGui::BeginCombo("preset", "choose...")) {
        for (std::size_t i = 0; i < in.scene.cameras.size(); ++i)
            if (ImGui::Selectable(in.scene.cameras[i].name.c_str())) state.cameraPreset = int(i);
        ImGui::EndCombo();
    }
    ImGui::Text("eye (%.3g, %.3g, %.3g)  fov %.1f°", camera.eye.x, camera.eye.y, camera.eye.z, camera.fovYDeg);
    ImGui::Text("move speed %.3g units/s (mouse wheel)", in.camera.speed());
}

bool lightsSection(ViewerState& state, const PanelInputs& in) {
    if (!ImGui::CollapsingHeader("Lights")) return false;
    bool anyChanged = false;
    for (std::size_t i = 0; i < state.lights.size(); ++i) {
        Light& light = state.lights[i];
        ImGui::PushID(int(i));
        const bool sun = light.type == LightType::Directional;
        const char* kind = sun ? "sun" : light.type == LightType::Spot ? "spot" : "point";
        ImGui::Text("%s %zu%s", kind, i, int(i) == steeredLight(state.lights) ? " (arrow keys)" : "");
        bool changed = false;
        if (light.type == LightType::Point) {
            glm::vec3 position(light.position);
            const float step = 0.005f * float(glm::length(in.scene.worldBounds.size()));
            if (ImGui::DragFloat3("position", &position.x, step, 0.0f, 0.0f, "%.3g")) {
                light.position = glm::dvec3(position);
                changed = true;
            }
        } else {
            LightAngles angles = anglesOfDirection(light.direction);
            float azimuth = float(angles.azimuthDeg), elevation = float(angles.elevationDeg);
            changed = ImGui::SliderFloat("azimuth", &azimuth, -180.0f, 180.0f, "%.1f°");
            changed |= ImGui::SliderFloat("elevation", &elevation, -89.0f, 89.0f, "%.1f°");
            if (changed) light.direction = directionOfAngles({azimuth, elevation});
        }
        float power = float(sun ? light.irradiance : light.intensity);
        if (ImGui::DragFloat(sun ? "irradiance W/m²" : "intensity W/sr", &power, std::max(power, 1e-3f) * 0.01f, 1e-4f,
                             1e7f, "%.4g", ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp)) {
            (sun ? light.irradiance : light.intensity) = double(power);
            changed = true;
        }
        anyChanged |= changed;
        ImGui::PopID();
    }
    return anyChanged;
}

bool comboOf(const char* label, int& index, const char* const items[], int count) {
    return ImGui::Combo(label, &index, items, count);
}

// A map resolution from a list (powers of two, and 6144 between the two finest), with `withAuto`
// also 0: "auto", follow the voxels (the photons' default). A value from the command line that is
// not in the list shows empty until one is picked.
bool resolutionCombo(const char* label, int& value, bool withAuto) {
    static const int resolutions[] = {0, 256, 512, 1024, 2048, 4096, 6144, 8192};
    static const char* const names[] = {"auto", "256", "512", "1024", "2048", "4096", "6144", "8192"};
    const int first = withAuto ? 0 : 1, count = int(std::size(resolutions)) - first;
    int index = int(std::find(std::begin(resolutions) + first, std::end(resolutions), value) - std::begin(resolutions)) - first;
    if (index == count) index = -1;
    if (!comboOf(label, index, names + first, count)) return false;
    value = resolutions[first + index];
    return true;
}

// Each widget reports an edit; `changed` collects them so the renderer is told only then.
void settingsSection(ViewerState& state, bool& changed) {
    if (!ImGui::CollapsingHeader("Settings")) return;
    RenderSettings& s = state.settings;
    // Not a render setting: how many still frames the viewer averages (no restart when it changes).
    ImGui::SliderInt("accumulate up to (samples per pixel)", &state.accumulateSamples, 1, 256, "%d",
                     ImGuiSliderFlags_AlwaysClamp);
    changed |= ImGui::Checkbox("GI (G)", &s.gi);
    changed |= ImGui::SliderInt("bounces (N)", &s.bounces, 1, kMaxBounces, "%d", ImGuiSliderFlags_AlwaysClamp);
    changed |= ImGui::SliderInt("narrow cones per voxel side, bounces (0 = the cone set)", &s.cones.bounceRays, 0,
                                kMaxBounceRays, "%d", ImGuiSliderFlags_AlwaysClamp);
    ImGui::SameLine();
    changed |= ImGui::Checkbox("photons (P)", &s.photons);
    ImGui::SameLine();
    changed |= ImGui::Checkbox("bricks (B)", &s.bricks);
    static const char* const giResolutions[] = {"every pixel", "2x2 blocks", "4x4 blocks", "auto"};
    static_assert(int(GiResolution::Full) == 0 && int(GiResolution::Half) == 1 && int(GiResolution::Quarter) == 2 &&
                  int(GiResolution::Auto) == 3);
    int giResolution = int(s.giResolution);
    if (ImGui::Combo("cones traced at (H)", &giResolution, giResolutions, 4)) {
        s.giResolution = GiResolution(giResolution);
        changed = true;
    }
    changed |= ImGui::SliderInt("narrow cones per pixel (C; 0 = the cone set)", &s.cones.rays, 0, kMaxNarrowCones, "%d",
                                ImGuiSliderFlags_AlwaysClamp);
    changed |= ImGui::Checkbox("narrow cones in later samples (at rest)", &s.cones.narrowConesAfterFirstSample);
    changed |= ImGui::Checkbox("near field from the G-buffer", &s.cones.nearField);
    changed |= ImGui::Checkbox("near field's detail at every pixel", &s.cones.nearDetail);
    changed |= ImGui::SliderFloat("cones shared with neighbours (voxels, 0 = off)", &s.cones.reuseVoxels, 0.0f, 16.0f,
                                  "%.1f", ImGuiSliderFlags_AlwaysClamp);
    changed |= ImGui::SliderFloat("cones carried over camera moves (voxels, 0 = off)", &s.cones.carryVoxels, 0.0f, 4.0f,
                                  "%.2f", ImGuiSliderFlags_AlwaysClamp);
    changed |= ImGui::SliderFloat("GI filter (voxels, 0 = off)", &s.giFilter, 0.0f, 16.0f, "%.1f",
                                  ImGuiSliderFlags_AlwaysClamp);

    static const char* const views[] = {"lit", "voxels (V)", "radiance (Shift+V)", "cones"};
    int view = int(s.view);
    if (comboOf("view", view, views, 4)) {
        s.view = ViewMode(view);
        changed = true;
    }
    int shownLevel = s.voxelViewLevel ? s.voxelViewLevel : s.voxelLevels;
    if (ImGui::SliderInt("view level [ ]", &shownLevel, 1, s.voxelLevels, "%d", ImGuiSliderFlags_AlwaysClamp)) {
        s.voxelViewLevel = shownLevel == s.voxelLevels ? 0 : shownLevel;
        changed = true;
    }

    static const Aov aovs[] = {Aov::Final, Aov::Direct, Aov::Indirect, Aov::Ao, Aov::Albedo, Aov::Normal, Aov::Depth, Aov::Gi};
    static const char* const aovNames[] = {"final (1)", "direct (2)", "indirect (3)", "ao (4)",
                                           "albedo (5)", "normal (6)", "depth", "gi (final - direct)"};
    int aov = int(std::find(std::begin(aovs), std::end(aovs), s.display.aov) - std::begin(aovs));
    if (comboOf("output", aov, aovNames, 8)) {
        s.display.aov = aovs[aov];
        changed = true;
    }
    float exposure = float(s.display.exposureEV);
    if (ImGui::SliderFloat("exposure EV", &exposure, -10.0f, 10.0f, "%.2f")) {
        s.display.exposureEV = exposure;
        changed = true;
    }
    static const char* const curves[] = {"aces", "reinhard", "clamp"};
    int curve = int(s.display.toneCurve);
    if (comboOf("tone curve", curve, curves, 3)) {
        s.display.toneCurve = ToneCurve(curve);
        changed = true;
    }
    changed |= ImGui::SliderFloat("GI scale", &s.display.giScale, 0.0f, 4.0f, "%.2f", ImGuiSliderFlags_AlwaysClamp);

    ImGui::Separator();
    static const int coneCounts[] = {1, 5, 6, 9, 16};
    static const char* const coneNames[] = {"1", "5", "6", "9", "16"};
    int cones = int(std::find(std::begin(coneCounts), std::end(coneCounts), s.cones.cones) - std::begin(coneCounts));
    if (comboOf("cones", cones, coneNames, 5)) {
        s.cones.cones = coneCounts[cones];
        changed = true;
    }
    changed |= ImGui::SliderFloat("aperture x", &s.cones.apertureScale, 0.1f, 4.0f, "%.2f", ImGuiSliderFlags_AlwaysClamp);
    if (ImGui::SliderFloat("step (diameters; 0: the cones' own)", &s.cones.step, 0.0f, 4.0f, "%.2f",
                           ImGuiSliderFlags_AlwaysClamp)) {
        if (s.cones.step > 0.0f) s.cones.step = std::max(s.cones.step, 0.05f);  // validateConeSettings' least
        changed = true;
    }
    changed |= ImGui::SliderFloat("offset (voxels)", &s.cones.offset, 0.0f, 16.0f, "%.2f", ImGuiSliderFlags_AlwaysClamp);
    changed |= ImGui::SliderFloat("lift", &s.cones.lift, 0.0f, 4.0f, "%.2f", ImGuiSliderFlags_AlwaysClamp);
    changed |= ImGui::SliderInt("PCF radius", &s.pcfRadius, 0, 8, "%d", ImGuiSliderFlags_AlwaysClamp);
    changed |= resolutionCombo("light-view map (photons)", s.lightViewResolution, true);
    changed |= resolutionCombo("shadow map", s.shadowMapResolution, false);
}

}  // namespace

PanelEdits UiPanel::draw(ViewerState& state, const PanelInputs& in) {
    PanelEdits edits;
    ImGui::SetNextWindowPos(ImVec2(8.0f, 8.0f), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(std::max(std::min(kPanelWidth, float(in.windowWidth) - 16.0f), 120.0f),
                                    std::max(std::min(float(in.windowHeight) - 16.0f, 900.0f), 80.0f)),
                             ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowBgAlpha(0.82f);
    if (!ImGui::Begin("vct (F1 hides)")) {
        ImGui::End();
        return edits;
    }
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextDisabled("%s", keyHelpLine().c_str());
    ImGui::PopTextWrapPos();
    if (!state.status.empty()) ImGui::TextColored(ImVec4(1.0f, 0.85f, 0.4f, 1.0f), "%s", state.status.c_str());
    frameSection(in);
    passesSection(in);
    memorySection(in);
    cameraSection(state, in);
    edits.lights = lightsSection(state, in);
    settingsSection(state, edits.settings);
    expensiveSection(state, edits.settings);
    ImGui::End();
    return edits;
}

void UiPanel::expensiveSection(ViewerState& state, bool& changed) {
    if (!ImGui::CollapsingHeader("Resolution (applied on release)")) return;
    // Rebuilding the octree or every render target per slider step would stall the viewer, so
    // these apply when the slider is let go.
    if (!ImGui::IsAnyItemActive()) {
        levels_ = state.settings.voxelLevels;
        scale_ = state.renderScale;
    }
    ImGui::SliderInt("voxel levels (2^L)", &levels_, 5, 10, "%d", ImGuiSliderFlags_AlwaysClamp);
    if (ImGui::IsItemDeactivatedAfterEdit() && levels_ != state.settings.voxelLevels) {
        state.settings.voxelLevels = levels_;
        if (state.settings.voxelViewLevel >= levels_) state.settings.voxelViewLevel = 0;
        changed = true;
    }
    ImGui::SliderFloat("render scale", &scale_, 0.25f, 1.0f, "%.2f", ImGuiSliderFlags_AlwaysClamp);
    if (ImGui::IsItemDeactivatedAfterEdit()) state.renderScale = scale_;  // the app resizes
}

}  // namespace vct::viewer
