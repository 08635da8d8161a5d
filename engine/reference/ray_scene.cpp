#include "reference/ray_scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>

#include "core/error.hpp"

namespace vct::reference {
namespace {

// Relative size of the spawn offset: the interpolated hit point is exact to a few float ulps of
// the largest coordinate involved (2⁻²³ relative); 2⁻¹⁶ leaves a margin of ~100× for Embree's
// own rounding in the next intersection test, and is still only 15 µm at 1 m.
constexpr float kRelativeOffset = 1.0f / 65536.0f;

void reportEmbreeError(void* /*user*/, RTCError code, const char* message) {
    // Errors are checked after each call through rtcGetDeviceError; nothing to do here but keep
    // Embree from printing on its own.
    (void)code;
    (void)message;
}

void checkDevice(RTCDevice device, const char* what) {
    const RTCError code = rtcGetDeviceError(device);
    if (code != RTC_ERROR_NONE) fail("Embree failed while ", what, " (error code ", int(code), ")");
}

// Embree intersection filter of alpha-masked geometries: rejects hits that fall into a hole of
// the material's alpha mask (alpha = baseAlpha · texel alpha < cutoff), for closest-hit and
// shadow rays alike, so every ray sees the same cut-outs as the rasterizer.
void alphaMaskFilter(const RTCFilterFunctionNArguments* args) {
    const auto* range = static_cast<const RayScene::RangeData*>(args->geometryUserPtr);
    const Scene& scene = *range->scene;
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        const unsigned prim = RTCHitN_primID(args->hit, args->N, i);
        const float u = RTCHitN_u(args->hit, args->N, i);
        const float v = RTCHitN_v(args->hit, args->N, i);
        const std::size_t first = 3 * (std::size_t(range->firstTriangle) + prim);
        const Vertex& a = scene.vertices[scene.indices[first]];
        const Vertex& b = scene.vertices[scene.indices[first + 1]];
        const Vertex& c = scene.vertices[scene.indices[first + 2]];
        const glm::vec2 uv0 = (1.0f - u - v) * a.uv + u * b.uv + v * c.uv;
        const glm::vec2 uv1 = (1.0f - u - v) * a.uv1 + u * b.uv1 + v * c.uv1;
        if (range->materials->cutsAway(range->material, uv0, uv1)) args->valid[i] = 0;
    }
}

// The unit normal of triangle abc, or `fallback` where it has none (zero area). The cross
// product's squared length goes with the fourth power of the scene's scale and leaves float's
// range beyond edges of about 1e9 (and below about 1e-9): then it is taken in double.
glm::vec3 unitNormal(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 fallback) {
    const glm::vec3 n = glm::cross(b - a, c - a);
    const float length = glm::length(n);
    if (length > 1e-15f && std::isfinite(length)) return n / length;
    const glm::dvec3 wide = glm::cross(glm::dvec3(b) - glm::dvec3(a), glm::dvec3(c) - glm::dvec3(a));
    const double wideLength = glm::length(wide);
    return wideLength > 0.0 && std::isfinite(wideLength) ? glm::vec3(wide / wideLength) : fallback;
}

float maxAbs(glm::vec3 p) { return std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}); }

}  // namespace

RayScene::RayScene(const Scene& scene, const MaterialTable& materials) : scene_(scene) {
    if (scene.vertices.empty() || scene.indices.empty()) fail("the scene has no triangles to trace");
    device_ = rtcNewDevice("verbose=0");
    if (!device_) fail("Embree could not create a device (error code ", int(rtcGetDeviceError(nullptr)), ")");
    rtcSetDeviceErrorFunction(device_, reportEmbreeError, nullptr);

    bool anyMasked = false;
    for (const DrawRange& r : scene.drawRanges) anyMasked |= materials.isMasked(r.material);
    if (anyMasked && !rtcGetDeviceProperty(device_, RTC_DEVICE_PROPERTY_FILTER_FUNCTION_SUPPORTED))
        fail("this Embree library was built without filter functions, which the alpha-masked materials need");

    const Bounds local = scene.localBounds();
    const float extent = float(std::max({std::abs(local.min.x), std::abs(local.min.y), std::abs(local.min.z),
                                         std::abs(local.max.x), std::abs(local.max.y), std::abs(local.max.z)}));
    scaleExponent_ = extent > 0.0f && std::isfinite(extent) ? -std::ilogb(extent) : 0;
    positions_.reserve(scene.vertices.size());
    for (const Vertex& v : scene.vertices)
        positions_.emplace_back(std::ldexp(v.position.x, scaleExponent_), std::ldexp(v.position.y, scaleExponent_),
                                std::ldexp(v.position.z, scaleExponent_), 0.0f);

    rtcScene_ = rtcNewScene(device_);
    rtcSetSceneFlags(rtcScene_, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(rtcScene_, RTC_BUILD_QUALITY_HIGH);
    ranges_.reserve(scene.drawRanges.size());  // stable addresses: Embree keeps pointers to them
    for (const DrawRange& r : scene.drawRanges) {
        if (r.indexCount == 0) continue;
        if (r.firstIndex % 3 || r.indexCount % 3 || std::size_t(r.firstIndex) + r.indexCount > scene.indices.size())
            fail("draw range of material ", r.material, " is not whole triangles (a loader bug: please report it)");
        ranges_.push_back({&scene, &materials, r.firstIndex / 3, r.material});
        RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
        rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, positions_.data(), 0,
                                   sizeof(glm::vec4), positions_.size());
        rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, scene.indices.data(),
                                   std::size_t(r.firstIndex) * sizeof(std::uint32_t), 3 * sizeof(std::uint32_t),
                                   r.indexCount / 3);
        if (materials.isMasked(r.material)) {
            rtcSetGeometryUserData(geometry, &ranges_.back());
            rtcSetGeometryIntersectFilterFunction(geometry, alphaMaskFilter);
            rtcSetGeometryOccludedFilterFunction(geometry, alphaMaskFilter);
        }
        rtcCommitGeometry(geometry);
        const unsigned id = rtcAttachGeometry(rtcScene_, geometry);
        rtcReleaseGeometry(geometry);
        if (id != ranges_.size() - 1) fail("Embree assigned geometry id ", id, " out of order");
        checkDevice(device_, "creating the triangle geometry");
    }
    rtcCommitScene(rtcScene_);
    checkDevice(device_, "building the BVH");

    // Even a hit at the local origin of a huge scene is computed from vertices that may be far
    // away: never offset by less than a much smaller fraction of the scene's extent.
    minimumOffset_ = std::max(extent * kRelativeOffset * 1e-3f, std::numeric_limits<float>::min());
}

RayScene::~RayScene() {
    if (rtcScene_) rtcReleaseScene(rtcScene_);
    if (device_) rtcReleaseDevice(device_);
}

RTCRay RayScene::embreeRay(glm::vec3 origin, glm::vec3 direction, float tFar) const {
    RTCRay ray;
    ray.org_x = std::ldexp(origin.x, scaleExponent_);
    ray.org_y = std::ldexp(origin.y, scaleExponent_);
    ray.org_z = std::ldexp(origin.z, scaleExponent_);
    ray.dir_x = direction.x;
    ray.dir_y = direction.y;
    ray.dir_z = direction.z;
    ray.tnear = 0.0f;
    ray.tfar = std::ldexp(tFar, scaleExponent_);
    ray.time = 0.0f;
    ray.mask = 0xffffffffu;
    ray.id = 0;
    ray.flags = 0;
    return ray;
}

std::optional<SurfaceHit> RayScene::intersect(glm::vec3 origin, glm::vec3 direction, float tFar) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh;
    rh.ray = embreeRay(origin, direction, tFar);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(rtcScene_, &context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;

    const RangeData& range = ranges_[rh.hit.geomID];
    const std::size_t first = 3 * (std::size_t(range.firstTriangle) + rh.hit.primID);
    const Vertex& a = scene_.vertices[scene_.indices[first]];
    const Vertex& b = scene_.vertices[scene_.indices[first + 1]];
    const Vertex& c = scene_.vertices[scene_.indices[first + 2]];
    const float u = rh.hit.u, v = rh.hit.v, w = 1.0f - u - v;

    SurfaceHit hit;
    hit.distance = std::ldexp(rh.ray.tfar, -scaleExponent_);
    hit.material = range.material;
    // The point from barycentrics, not origin + t·direction: its error is relative to the
    // triangle's coordinates, not to the (possibly long) ray.
    hit.position = w * a.position + u * b.position + v * c.position;
    hit.uv = w * a.uv + u * b.uv + v * c.uv;
    hit.uv1 = w * a.uv1 + u * b.uv1 + v * c.uv1;
    hit.color = w * a.color + u * b.color + v * c.color;
    hit.geometricNormal = unitNormal(a.position, b.position, c.position, -direction);
    const glm::vec3 ns = w * a.normal + u * b.normal + v * c.normal;
    const float nsLength2 = glm::dot(ns, ns);
    hit.shadingNormal = nsLength2 > 1e-24f && std::isfinite(nsLength2) ? ns / std::sqrt(nsLength2) : hit.geometricNormal;
    const float magnitude = std::max({maxAbs(a.position), maxAbs(b.position), maxAbs(c.position)});
    hit.offset = std::max(magnitude * kRelativeOffset, minimumOffset_);
    const glm::vec3 toCentroid = (a.position + b.position + c.position) / 3.0f - hit.position;
    const float centroidDistance = glm::length(toCentroid);
    if (centroidDistance > 0.0f && std::isfinite(centroidDistance))  // never past half-way to the centroid
        hit.inward = toCentroid * (std::min(hit.offset, 0.5f * centroidDistance) / centroidDistance);
    return hit;
}

bool RayScene::occluded(glm::vec3 origin, glm::vec3 direction, float tFar) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay ray = embreeRay(origin, direction, tFar);
    rtcOccluded1(rtcScene_, &context, &ray);
    return ray.tfar < 0.0f;  // Embree sets tfar = −inf on a hit
}

}  // namespace vct::reference
