#include "bench/sweep.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>

#include "core/error.hpp"
#include "lighting/bounce_gather.hpp"
#include "render/pixel_samples.hpp"
#include "voxel/voxel_grid.hpp"

namespace vct::bench {
namespace {

using Json = nlohmann::ordered_json;

std::string formatNumber(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

int integer(const Json& v, const std::string& what, int lo, int hi) {
    if (!v.is_number_integer() && !(v.is_number_float() && std::floor(v.get<double>()) == v.get<double>()))
        fail(what, " must be an integer, not ", v.dump());
    const double d = v.get<double>();
    if (d < lo || d > hi) fail(what, " ", v.dump(), " is out of range; use ", lo, "..", hi);
    return int(d);
}

double number(const Json& v, const std::string& what, double lo, double hi) {
    if (!v.is_number()) fail(what, " must be a number, not ", v.dump());
    const double d = v.get<double>();
    if (!std::isfinite(d) || d < lo || d > hi) fail(what, " ", v.dump(), " is out of range; use ", lo, "..", hi);
    return d;
}

bool boolean(const Json& v, const std::string& what) {
    if (!v.is_boolean()) fail(what, " must be true or false, not ", v.dump());
    return v.get<bool>();
}

void checkKeys(const Json& object, const std::string& what, const std::set<std::string>& allowed) {
    if (!object.is_object()) fail(what, " must be a JSON object");
    for (const auto& [key, value] : object.items())
        if (!allowed.count(key)) {
            std::string list;
            for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
            fail("unknown key '", key, "' in ", what, "; the keys are ", list);
        }
}

glm::dvec3 point(const Json& v, const std::string& what) {
    if (!v.is_array() || v.size() != 3) fail(what, " must be a list of three numbers [x, y, z]");
    return {number(v[0], what, -1e30, 1e30), number(v[1], what, -1e30, 1e30), number(v[2], what, -1e30, 1e30)};
}

// "camera": a preset's name, or an object whose keys move the preset's view (checked again,
// with the scene, when the camera is made).
void parseCamera(const Json& camera, SweepDefinition& s) {
    if (camera.is_string()) {
        s.camera = camera.get<std::string>();
        return;
    }
    if (!camera.is_object()) fail("'camera' must be a preset name or an object {\"preset\", \"eye\", \"target\", \"up\", \"fov\"}");
    checkKeys(camera, "'camera'", {"preset", "eye", "target", "up", "fov"});
    if (camera.contains("preset")) {
        if (!camera["preset"].is_string()) fail("'camera.preset' must be a preset name");
        s.camera = camera["preset"].get<std::string>();
    }
    if (camera.contains("eye")) s.view.eye = point(camera["eye"], "'camera.eye'");
    if (camera.contains("target")) s.view.target = point(camera["target"], "'camera.target'");
    if (camera.contains("up")) s.view.up = point(camera["up"], "'camera.up'");
    if (camera.contains("fov")) s.view.fovYDeg = number(camera["fov"], "'camera.fov'", 1e-3, 179.999);
}

}  // namespace

const std::vector<std::string>& parameterNames() {
    static const std::vector<std::string> names = {"voxel_levels", "cones",          "cone_aperture", "cone_step",
                                                   "cone_offset",  "cone_lift",      "bricks",        "light_view_res",
                                                   "pcf_radius",   "gi",             "bounces",       "samples",
                                                   "gi_resolution", "shadow_res",    "gi_filter",     "cone_rays",
                                                   "sample_cones", "cone_reuse",     "bounce_cone_rays", "near_field",
                                                   "near_detail"};
    return names;
}

void applyParameter(PointSettings& s, const std::string& name, const Json& v) {
    const std::string what = "'" + name + "'";
    if (name == "voxel_levels") {
        s.voxelLevels = integer(v, what, kMinVoxelLevels, kMaxVoxelLevels);
    } else if (name == "cones") {
        const int n = integer(v, what, 1, 16);
        if (n != 1 && n != 5 && n != 6 && n != 9 && n != 16) fail(what, " ", n, " is not a cone set; use 1, 5, 6, 9 or 16");
        s.cones.cones = n;
    } else if (name == "cone_rays") {
        s.cones.rays = integer(v, what, 0, 64);
        validateConeSettings(s.cones);
    } else if (name == "bounce_cone_rays") {
        s.cones.bounceRays = integer(v, what, 0, kMaxBounceRays);
        validateConeSettings(s.cones);
    } else if (name == "sample_cones") {
        if (!v.is_string()) fail(what, " must be \"narrow\" or \"frame\"");
        try {
            s.cones.narrowConesAfterFirstSample = parseSampleCones(v.get<std::string>());
        } catch (const Error&) {
            fail(what, " must be \"narrow\" or \"frame\", not \"", v.get<std::string>(), "\"");
        }
    } else if (name == "cone_reuse") {
        s.cones.reuseVoxels = float(number(v, what, 0.0, 64.0));
    } else if (name == "near_field") {
        s.cones.nearField = boolean(v, what);
    } else if (name == "near_detail") {
        s.cones.nearDetail = boolean(v, what);
    } else if (name == "cone_aperture") {
        s.cones.apertureScale = float(number(v, what, 1e-3, 4.0));
    } else if (name == "cone_step") {
        s.cones.step = float(number(v, what, 0.0, 4.0));
        validateConeSettings(s.cones);
    } else if (name == "cone_offset") {
        s.cones.offset = float(number(v, what, 0.0, 16.0));
    } else if (name == "cone_lift") {
        s.cones.lift = float(number(v, what, 0.0, 4.0));
    } else if (name == "bricks") {
        s.bricks = boolean(v, what);
    } else if (name == "light_view_res") {
        s.lightViewResolution = integer(v, what, 0, kMaxImageSide);
        if (s.lightViewResolution > 0 && s.lightViewResolution < 16)
            fail(what, " ", s.lightViewResolution, " is out of range; use 16..", kMaxImageSide, " or 0 (follow the voxels)");
    } else if (name == "pcf_radius") {
        s.pcfRadius = integer(v, what, 0, 8);
    } else if (name == "gi") {
        s.gi = boolean(v, what);
    } else if (name == "bounces") {
        s.bounces = integer(v, what, 1, kMaxBounces);
    } else if (name == "samples") {
        s.pixelSamples = integer(v, what, 1, kMaxPixelSamples);
    } else if (name == "shadow_res") {
        s.shadowMapResolution = integer(v, what, 16, kMaxImageSide);
    } else if (name == "gi_filter") {
        s.giFilter = float(number(v, what, 0.0, 64.0));
    } else if (name == "gi_resolution") {
        if (!v.is_string()) fail(what, " must be \"full\" or \"half\"");
        try {
            s.giResolution = parseGiResolution(v.get<std::string>());
        } catch (const Error&) {
            fail(what, " must be \"full\" or \"half\", not \"", v.get<std::string>(), "\"");
        }
    } else {
        std::string list;
        for (const auto& p : parameterNames()) list += (list.empty() ? "" : ", ") + p;
        fail("unknown parameter '", name, "'; the parameters are ", list);
    }
}

std::string parameterValue(const PointSettings& s, const std::string& name) {
    if (name == "voxel_levels") return std::to_string(s.voxelLevels);
    if (name == "cones") return std::to_string(s.cones.cones);
    if (name == "cone_rays") return std::to_string(s.cones.rays);
    if (name == "bounce_cone_rays") return std::to_string(s.cones.bounceRays);
    if (name == "sample_cones") return sampleConesName(s.cones.narrowConesAfterFirstSample);
    if (name == "cone_reuse") return formatNumber(s.cones.reuseVoxels);
    if (name == "near_field") return s.cones.nearField ? "true" : "false";
    if (name == "near_detail") return s.cones.nearDetail ? "true" : "false";
    if (name == "cone_aperture") return formatNumber(s.cones.apertureScale);
    if (name == "cone_step") return formatNumber(s.cones.step);
    if (name == "cone_offset") return formatNumber(s.cones.offset);
    if (name == "cone_lift") return formatNumber(s.cones.lift);
    if (name == "bricks") return s.bricks ? "true" : "false";
    if (name == "light_view_res") return std::to_string(s.lightViewResolution);
    if (name == "pcf_radius") return std::to_string(s.pcfRadius);
    if (name == "gi") return s.gi ? "true" : "false";
    if (name == "bounces") return std::to_string(s.bounces);
    if (name == "samples") return std::to_string(s.pixelSamples);
    if (name == "gi_resolution") return giResolutionName(s.giResolution);
    if (name == "shadow_res") return std::to_string(s.shadowMapResolution);
    if (name == "gi_filter") return formatNumber(s.giFilter);
    fail("unknown parameter '", name, "'");
}

SweepDefinition parseSweep(const Json& j, const std::string& name, const std::filesystem::path& file) {
    SweepDefinition s;
    s.name = name;
    s.file = file;
    const std::string in = " in " + (file.empty() ? std::string("the sweep") : file.string());
    try {
        checkKeys(j, "the sweep definition",
                  {"name", "scene", "camera", "width", "height", "exposure", "tonemap", "repeats", "reference",
                   "pathtracer_curve", "default", "sweep", "comment"});
        if (j.contains("name")) {
            if (!j["name"].is_string() || j["name"].get<std::string>().empty()) fail("'name' must be a non-empty string");
            s.name = j["name"].get<std::string>();
            for (char c : s.name)
                if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-'))
                    fail("'name' may only hold letters, digits, '_' and '-' (it names the output files)");
        }
        if (j.contains("scene")) {
            if (!j["scene"].is_string()) fail("'scene' must be a string: cornell, sponza or a model path");
            s.scene = j["scene"].get<std::string>();
        }
        if (j.contains("camera")) parseCamera(j["camera"], s);
        if (j.contains("width")) s.width = integer(j["width"], "'width'", 1, kMaxImageSide);
        if (j.contains("height")) s.height = integer(j["height"], "'height'", 1, kMaxImageSide);
        if (j.contains("exposure")) s.exposureEV = number(j["exposure"], "'exposure'", -64, 64);
        if (j.contains("tonemap")) {
            if (!j["tonemap"].is_string()) fail("'tonemap' must be aces, reinhard or clamp");
            s.tonemap = j["tonemap"].get<std::string>();
        }
        if (j.contains("repeats")) s.repeats = integer(j["repeats"], "'repeats'", 1, 100);
        if (j.contains("reference")) {
            const Json& r = j["reference"];
            checkKeys(r, "'reference'", {"bounces", "spp", "seed"});
            if (r.contains("bounces")) s.referenceBounces = integer(r["bounces"], "'reference.bounces'", 0, 1024);
            if (r.contains("spp")) s.referenceSpp = integer(r["spp"], "'reference.spp'", 1, 1 << 24);
            if (r.contains("seed")) s.referenceSeed = std::uint64_t(integer(r["seed"], "'reference.seed'", 0, 1 << 30));
        }
        s.curveSeed = s.referenceSeed + 1;
        if (j.contains("pathtracer_curve")) {
            const Json& c = j["pathtracer_curve"];
            checkKeys(c, "'pathtracer_curve'", {"spp", "seed"});
            if (c.contains("spp")) {
                if (!c["spp"].is_array() || c["spp"].empty()) fail("'pathtracer_curve.spp' must be a list of spp values");
                s.curveSpp.clear();
                for (const auto& v : c["spp"]) s.curveSpp.push_back(integer(v, "'pathtracer_curve.spp'", 1, 1 << 24));
                for (std::size_t i = 1; i < s.curveSpp.size(); ++i)
                    if (s.curveSpp[i] <= s.curveSpp[i - 1]) fail("'pathtracer_curve.spp' must increase");
            }
            if (c.contains("seed")) s.curveSeed = std::uint64_t(integer(c["seed"], "'pathtracer_curve.seed'", 0, 1 << 30));
            if (s.curveSeed == s.referenceSeed)
                fail("'pathtracer_curve.seed' must differ from the reference's seed (else the curve shares the "
                     "reference's samples and its error is underestimated)");
        }
        if (j.contains("default")) {
            const Json& d = j["default"];
            if (!d.is_object()) fail("'default' must be an object of parameters");
            for (const auto& [key, value] : d.items()) applyParameter(s.defaults, key, value);
        }
        if (j.contains("sweep")) {
            const Json& w = j["sweep"];
            if (!w.is_object()) fail("'sweep' must be an object: parameter → list of values");
            for (const auto& [key, values] : w.items()) {
                if (!values.is_array()) fail("'sweep.", key, "' must be a list of values");
                PointSettings probe = s.defaults;
                std::vector<Json> list;
                for (const auto& v : values) {
                    applyParameter(probe, key, v);  // checks name, type and range
                    list.push_back(v);
                }
                s.sweep.emplace_back(key, std::move(list));
            }
        }
    } catch (const Error& e) {
        fail(e.what(), in);
    }
    return s;
}

SweepDefinition loadSweep(const std::filesystem::path& file) {
    std::ifstream in(file);
    if (!in) fail("cannot read the sweep file '", file.string(), "'; check the path (benchmarks/sweeps/ holds cornell.json, "
                  "sponza.json and quick.json)");
    Json j;
    try {
        j = Json::parse(in, nullptr, true, true);  // comments allowed
    } catch (const nlohmann::json::parse_error& e) {
        fail("the sweep file '", file.string(), "' is not valid JSON: ", e.what());
    }
    return parseSweep(j, file.stem().string(), file);
}

std::vector<SweepPoint> expandSweep(const SweepDefinition& sweep) {
    std::vector<SweepPoint> points;
    SweepPoint base;
    base.label = "default";
    base.settings = sweep.defaults;
    base.isDefault = true;
    points.push_back(base);
    std::set<std::string> seen;
    for (const auto& [parameter, values] : sweep.sweep) {
        const std::string defaultValue = parameterValue(sweep.defaults, parameter);
        for (const auto& v : values) {
            SweepPoint p;
            p.parameter = parameter;
            p.settings = sweep.defaults;
            applyParameter(p.settings, parameter, v);
            p.value = parameterValue(p.settings, parameter);
            if (p.value == defaultValue) continue;  // that is the default point
            p.label = parameter + "=" + p.value;
            if (!seen.insert(p.label).second) continue;  // listed twice
            points.push_back(std::move(p));
        }
    }
    return points;
}

std::string resolveScenePath(const SweepDefinition& sweep) {
    if (sweep.scene == "cornell" || sweep.scene == "sponza" || sweep.file.empty()) return sweep.scene;
    const std::filesystem::path p(sweep.scene);
    if (p.is_absolute()) return sweep.scene;
    return (sweep.file.parent_path() / p).string();
}

}  // namespace vct::bench
