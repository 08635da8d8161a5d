#include "cli/scene_options.hpp"

#include <string_view>

#include "core/error.hpp"
#include "scene/scene_loader.hpp"

namespace vct::cli {
namespace {

glm::dvec3 toVec3(const std::vector<double>& values, const char* option) {
    if (values.size() != 3) fail(option, " needs three comma-separated numbers, e.g. ", option, " 0,1,0");
    return {values[0], values[1], values[2]};
}

void addVector(CLI::App& command, const std::string& name, std::vector<double>& target, const std::string& help) {
    command.add_option(name, target, help)->delimiter(',')->type_name("X,Y,Z");
}

// Whether `name` matches `pattern`, in which '*' stands for any run of characters.
bool matchesPattern(std::string_view name, std::string_view pattern) {
    std::size_t n = 0, p = 0, starAt = std::string_view::npos, matchedAtStar = 0;
    while (n < name.size()) {
        if (p < pattern.size() && pattern[p] == '*') {
            starAt = p++;
            matchedAtStar = n;
        } else if (p < pattern.size() && pattern[p] == name[n]) {
            ++p;
            ++n;
        } else if (starAt != std::string_view::npos) {
            p = starAt + 1;
            n = ++matchedAtStar;
        } else {
            return false;
        }
    }
    while (p < pattern.size() && pattern[p] == '*') ++p;
    return p == pattern.size();
}

// A material that reflects nothing still blocks light and casts shadows: the difference between
// a frame with and without it is, on the pixels that do not show the material itself (which it
// darkens too), the light that reaches the image off that material. Done the same way in `render`
// and `reference`, it says which surfaces' light the engine gets wrong.
void darkenMaterials(Scene& scene, const std::vector<std::string>& patterns) {
    for (const std::string& pattern : patterns) {
        std::size_t matched = 0;
        for (Material& material : scene.materials)
            if (matchesPattern(material.name, pattern)) {
                material.baseColor = glm::vec3(0.0f);
                ++matched;
            }
        if (matched) continue;
        std::string names;
        for (const Material& material : scene.materials) names += (names.empty() ? "" : ", ") + material.name;
        fail("--dark-material '", pattern, "' matches none of the scene's materials (", names,
             "); give a name from that list, with '*' for any characters");
    }
}

const Light* firstOfType(const std::vector<Light>& lights, LightType type) {
    for (const auto& light : lights)
        if (light.type == type) return &light;
    return nullptr;
}

}  // namespace

void addSceneOptions(CLI::App& command, SceneOptions& o, bool withCameraAndLights) {
    command.add_option("--scene", o.scene, "cornell (built in), sponza (asset search path) or a model file path")
        ->capture_default_str();
    command.add_flag("--sanitize", o.sanitize,
                     "drop triangles with non-finite vertex positions instead of refusing the model");
    if (!withCameraAndLights) return;
    command.add_option("--camera", o.cameraPreset, "camera preset name (the scene's presets are listed by vct info)");
    addVector(command, "--eye", o.eye, "camera position (world units)");
    addVector(command, "--target", o.target, "point the camera looks at");
    addVector(command, "--up", o.up, "camera up vector (default 0,1,0)");
    command.add_option("--fov", o.fovDeg, "vertical field of view in degrees");
    addVector(command, "--sun-dir", o.sunDirection, "sun: direction the light travels, e.g. 0.3,-1,0.2");
    command.add_option("--sun-irradiance", o.sunIrradiance, "sun: irradiance E in W/m² perpendicular to the light");
    addVector(command, "--spot-pos", o.spotPosition, "spot light position");
    addVector(command, "--spot-dir", o.spotDirection, "spot light axis (direction the light travels)");
    command.add_option("--spot-intensity", o.spotIntensity, "spot: intensity I in W/sr on its axis");
    command.add_option("--spot-angles", o.spotAngles, "spot: inner,outer half-angles in degrees (falloff between)")
        ->delimiter(',')
        ->type_name("INNER,OUTER");
    addVector(command, "--point-pos", o.pointPosition, "point light position");
    command.add_option("--point-intensity", o.pointIntensity, "point light: intensity I in W/sr in every direction");
    addVector(command, "--light-color", o.lightColor, "linear RGB tint of the lights given on the command line");
    command.add_option("--dark-material", o.darkMaterials,
                       "diagnostic: this material (a name, '*' for any characters; repeatable) reflects no light; "
                       "it still blocks light, and its emission stays")
        ->type_name("NAME");
}

Scene loadSceneFromOptions(const SceneOptions& o) {
    Scene scene = loadScene(o.scene, LoadOptions{o.sanitize});
    darkenMaterials(scene, o.darkMaterials);
    const bool sun = !o.sunDirection.empty() || o.sunIrradiance;
    const bool spot = !o.spotPosition.empty() || !o.spotDirection.empty() || o.spotIntensity || !o.spotAngles.empty();
    const bool point = !o.pointPosition.empty() || o.pointIntensity;
    if (!sun && !spot && !point) {
        // Nothing is silently ignored: the tint belongs to lights given here.
        if (!o.lightColor.empty())
            fail("--light-color tints the lights given on the command line; add --sun-dir/--sun-irradiance or "
                 "--spot-pos/--spot-dir/--spot-intensity/--spot-angles or --point-pos/--point-intensity");
        return scene;
    }
    const glm::dvec3 color = o.lightColor.empty() ? glm::dvec3(1.0) : toVec3(o.lightColor, "--light-color");
    std::vector<Light> lights;
    // Each light starts from the scene's own light of its type (or a default one) and is checked
    // and tinted alike.
    auto add = [&](Light light, const char* what) {
        light.color = color;
        validateLight(light, what);
        if (light.type != LightType::Point) light.direction = glm::normalize(light.direction);
        lights.push_back(light);
    };
    if (sun) {
        const Light* own = firstOfType(scene.lights, LightType::Directional);
        Light light = own ? *own : Light{};
        light.type = LightType::Directional;
        if (!own) light.direction = glm::normalize(glm::dvec3(-0.3, -1.0, -0.2));
        if (!o.sunDirection.empty()) light.direction = toVec3(o.sunDirection, "--sun-dir");
        if (o.sunIrradiance) light.irradiance = *o.sunIrradiance;
        add(light, "the sun given on the command line");
    }
    if (spot) {
        const Light* own = firstOfType(scene.lights, LightType::Spot);
        Light light = own ? *own : Light{};
        light.type = LightType::Spot;
        if (!own) light.position = scene.worldBounds.centre() + glm::dvec3(0.0, 0.45 * scene.worldBounds.size().y, 0.0);
        if (!o.spotPosition.empty()) light.position = toVec3(o.spotPosition, "--spot-pos");
        if (!o.spotDirection.empty()) light.direction = toVec3(o.spotDirection, "--spot-dir");
        if (o.spotIntensity) light.intensity = *o.spotIntensity;
        if (!o.spotAngles.empty()) {
            if (o.spotAngles.size() != 2) fail("--spot-angles needs two numbers: inner,outer (degrees)");
            light.innerAngleDeg = o.spotAngles[0];
            light.outerAngleDeg = o.spotAngles[1];
        }
        add(light, "the spot light given on the command line");
    }
    if (point) {
        const Light* own = firstOfType(scene.lights, LightType::Point);
        Light light = own ? *own : Light{};
        light.type = LightType::Point;
        // Without a position: in the middle of the scene, a little above its centre.
        if (!own) light.position = scene.worldBounds.centre() + glm::dvec3(0.0, 0.25 * scene.worldBounds.size().y, 0.0);
        if (!o.pointPosition.empty()) light.position = toVec3(o.pointPosition, "--point-pos");
        if (o.pointIntensity) light.intensity = *o.pointIntensity;
        add(light, "the point light given on the command line");
    }
    scene.lights = lights;
    return scene;
}

Camera cameraFromOptions(const SceneOptions& o, const Scene& scene) {
    CameraChanges changes;
    if (!o.eye.empty()) changes.eye = toVec3(o.eye, "--eye");
    if (!o.target.empty()) changes.target = toVec3(o.target, "--target");
    if (!o.up.empty()) changes.up = toVec3(o.up, "--up");
    changes.fovYDeg = o.fovDeg;
    return changedCamera(o.cameraPreset.empty() ? scene.cameras.at(0) : scene.camera(o.cameraPreset), changes);
}

}  // namespace vct::cli
