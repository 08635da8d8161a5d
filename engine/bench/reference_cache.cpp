#include "bench/reference_cache.hpp"

#include <cstring>
#include <fstream>
#include <type_traits>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/log.hpp"
#include "metrics/image_metrics.hpp"

namespace vct::bench {
namespace {

// FNV-1a style mixing over 64-bit words (fast enough for Sponza's few hundred MB of texels).
class Hasher {
public:
    void bytes(const void* data, std::size_t size) {
        const auto* p = static_cast<const unsigned char*>(data);
        std::size_t i = 0;
        for (; i + 8 <= size; i += 8) {
            std::uint64_t word;
            std::memcpy(&word, p + i, 8);
            mix(word);
        }
        std::uint64_t tail = 0;
        if (size > i) std::memcpy(&tail, p + i, size - i);
        mix(tail ^ (std::uint64_t(size - i) << 56));
        mix(size);
    }
    template <class T>
    void value(const T& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        bytes(&v, sizeof v);
    }
    void string(const std::string& s) { bytes(s.data(), s.size()); }
    void vec3(const glm::dvec3& v) { value(v.x), value(v.y), value(v.z); }
    void vec3(const glm::vec3& v) { value(v.x), value(v.y), value(v.z); }
    std::uint64_t digest() const {
        std::uint64_t h = h_;
        h ^= h >> 33;
        h *= 0xff51afd7ed558ccdull;
        h ^= h >> 33;
        return h;
    }

private:
    void mix(std::uint64_t word) {
        h_ ^= word;
        h_ *= 0x100000001b3ull;
        h_ ^= h_ >> 29;
    }
    std::uint64_t h_ = 0xcbf29ce484222325ull;
};

std::string hex(std::uint64_t v) {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(v));
    return text;
}

std::string safeName(const std::string& name) {
    std::string s;
    for (char c : name) s += (std::isalnum(static_cast<unsigned char>(c)) || c == '-') ? c : '_';
    return s.empty() ? "scene" : s;
}

reference::ReferenceResult render(const Scene& scene, const Camera& camera, const reference::ReferenceSettings& s,
                                  const char* what) {
    logInfo(concat("bench: rendering the ", what, " reference: ", s.width, "x", s.height, ", ", s.samplesPerPixel,
                   " spp, bounces ", s.bounces, ", seed ", s.seed, " (cached afterwards)"));
    return reference::renderReference(scene, camera, s);
}

void writeAtomically(const std::filesystem::path& path, const ImageF& image) {
    const std::filesystem::path tmp = path.string() + ".tmp.pfm";
    writeHdrImage(tmp, image);
    std::filesystem::rename(tmp, path);
}

}  // namespace

std::uint64_t sceneContentHash(const Scene& scene) {
    Hasher h;
    h.string(scene.name);
    h.vec3(scene.origin);
    h.value(scene.vertices.size());
    for (const Vertex& v : scene.vertices) {
        h.vec3(v.position), h.vec3(v.normal), h.value(v.uv.x), h.value(v.uv.y);
        h.value(v.uv1.x), h.value(v.uv1.y), h.vec3(v.color);
    }
    h.bytes(scene.indices.data(), scene.indices.size() * sizeof(std::uint32_t));
    for (const DrawRange& r : scene.drawRanges) h.value(r.firstIndex), h.value(r.indexCount), h.value(r.material);
    for (const Material& m : scene.materials) {
        h.vec3(m.baseColor);
        h.value(m.baseColorTexture);
        h.value(int(m.alphaMode));
        h.value(m.alphaCutoff);
        h.value(m.baseAlpha);
        h.vec3(m.emissive);
        const TextureMapping& t = m.baseColorMapping;
        h.value(t.texCoord), h.value(int(t.wrapS)), h.value(int(t.wrapT));
        for (int c = 0; c < 3; ++c) h.vec3(t.transform[c]);
    }
    for (const Texture& t : scene.textures) {
        h.value(t.width);
        h.value(t.height);
        h.bytes(t.rgba.data(), t.rgba.size());
    }
    return h.digest();
}

std::string referenceKey(const Scene& scene, const Camera& camera, const reference::ReferenceSettings& s) {
    Hasher h;
    h.value(kReferenceCacheVersion);
    h.value(sceneContentHash(scene));
    h.vec3(camera.eye);
    h.vec3(camera.target);
    h.vec3(camera.up);
    h.value(camera.fovYDeg);
    // Every field of Light is part of the key: a field added to Light must be added here too.
    static_assert(sizeof(Light) == 8 + 3 * sizeof(glm::dvec3) + 4 * sizeof(double),
                  "Light changed: add its new field to the reference cache key");
    for (const Light& l : scene.lights) {
        h.value(int(l.type));
        h.vec3(l.position);
        h.vec3(l.direction);
        h.vec3(l.color);
        h.value(l.irradiance);
        h.value(l.intensity);
        h.value(l.innerAngleDeg);
        h.value(l.outerAngleDeg);
    }
    h.value(s.width);
    h.value(s.height);
    h.value(s.samplesPerPixel);
    h.value(s.bounces);
    h.value(s.seed);
    h.value(s.centerOnly);
    return hex(h.digest());
}

ImageF subtractImages(const ImageF& a, const ImageF& b) {
    metrics::checkSameSize(a, b, "image", "image subtracted");
    ImageF d = a;
    for (std::size_t i = 0; i < d.rgba.size(); i += 4)
        for (int c = 0; c < 3; ++c) d.rgba[i + c] = a.rgba[i + c] - b.rgba[i + c];
    return d;
}

ReferenceImages loadOrRenderReference(const Scene& scene, const Camera& camera,
                                      const reference::ReferenceSettings& settings,
                                      const std::filesystem::path& cacheDir, bool useCache) {
    reference::validate(settings);
    ReferenceImages r;
    r.key = referenceKey(scene, camera, settings);
    r.spp = settings.samplesPerPixel;
    r.bounces = settings.bounces;
    r.seed = settings.seed;
    const std::string stem = "ref_" + safeName(scene.name) + "_" + r.key;
    r.fullPath = cacheDir / (stem + "_full.pfm");
    r.directPath = cacheDir / (stem + "_direct.pfm");
    const std::filesystem::path metaPath = cacheDir / (stem + ".json");

    if (useCache && std::filesystem::exists(r.fullPath) && std::filesystem::exists(r.directPath) &&
        std::filesystem::exists(metaPath)) {
        try {
            std::ifstream in(metaPath);
            const nlohmann::json meta = nlohmann::json::parse(in);
            r.full = readHdrImage(r.fullPath);
            r.direct = readHdrImage(r.directPath);
            if (r.full.width == settings.width && r.full.height == settings.height && r.direct.width == settings.width &&
                r.direct.height == settings.height) {
                r.seconds = meta.at("seconds").get<double>();
                r.directSeconds = meta.at("direct_seconds").get<double>();
                r.meanVariance = meta.at("mean_variance").get<double>();
                r.threads = meta.at("threads").get<int>();
                r.indirect = subtractImages(r.full, r.direct);
                r.fromCache = true;
                logInfo(concat("bench: reference from the cache: ", r.fullPath.string()));
                return r;
            }
        } catch (const std::exception& e) {
            logWarn(concat("bench: ignoring the unreadable cache entry ", metaPath.string(), " (", e.what(),
                           "); rendering the reference again"));
        }
    }

    std::filesystem::create_directories(cacheDir);
    ensureWritable(metaPath);
    const reference::ReferenceResult full = render(scene, camera, settings, "full");
    reference::ReferenceSettings directSettings = settings;
    directSettings.bounces = 0;
    const reference::ReferenceResult direct = render(scene, camera, directSettings, "direct-only");
    r.full = full.radiance;
    r.direct = direct.radiance;
    r.indirect = subtractImages(r.full, r.direct);
    r.seconds = full.seconds;
    r.directSeconds = direct.seconds;
    r.meanVariance = full.meanVariance;
    r.threads = full.threads;

    writeAtomically(r.fullPath, r.full);
    writeAtomically(r.directPath, r.direct);
    nlohmann::ordered_json meta;
    meta["scene"] = scene.name;
    meta["source"] = scene.sourcePath;
    meta["key"] = r.key;
    meta["cache_version"] = kReferenceCacheVersion;
    meta["camera"] = {{"eye", {camera.eye.x, camera.eye.y, camera.eye.z}},
                      {"target", {camera.target.x, camera.target.y, camera.target.z}},
                      {"fov", camera.fovYDeg}};
    meta["width"] = settings.width;
    meta["height"] = settings.height;
    meta["spp"] = settings.samplesPerPixel;
    meta["bounces"] = settings.bounces;
    meta["seed"] = settings.seed;
    meta["seconds"] = r.seconds;
    meta["direct_seconds"] = r.directSeconds;
    meta["mean_variance"] = r.meanVariance;
    meta["threads"] = r.threads;
    {
        const std::filesystem::path tmp = metaPath.string() + ".tmp";
        std::ofstream out(tmp);
        out << meta.dump(2) << "\n";
        if (!out) fail("cannot write '", tmp.string(), "' (disk full?)");
        out.close();
        std::filesystem::rename(tmp, metaPath);
    }
    return r;
}

}  // namespace vct::bench
