// The built-in Cornell box: geometry, materials, light, camera, exposure.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "core/error.hpp"
#include "scene/scene_loader.hpp"

namespace {

using vct::Scene;

const vct::Material& materialNamed(const Scene& scene, const std::string& name) {
    for (const vct::Material& m : scene.materials)
        if (m.name == name) return m;
    ADD_FAILURE() << "no material named " << name;
    return scene.materials.at(0);
}

struct Triangle {
    glm::dvec3 a, b, c;      // world space
    glm::dvec3 faceNormal;   // from the winding
    glm::dvec3 vertexNormal; // first vertex's normal
    std::uint32_t material;
};

std::vector<Triangle> triangles(const Scene& scene) {
    std::vector<Triangle> out;
    for (const vct::DrawRange& range : scene.drawRanges)
        for (std::uint32_t i = range.firstIndex; i < range.firstIndex + range.indexCount; i += 3) {
            Triangle t;
            const auto& v0 = scene.vertices[scene.indices[i]];
            const auto& v1 = scene.vertices[scene.indices[i + 1]];
            const auto& v2 = scene.vertices[scene.indices[i + 2]];
            t.a = glm::dvec3(v0.position) + scene.origin;
            t.b = glm::dvec3(v1.position) + scene.origin;
            t.c = glm::dvec3(v2.position) + scene.origin;
            t.faceNormal = glm::normalize(glm::cross(t.b - t.a, t.c - t.a));
            t.vertexNormal = glm::dvec3(v0.normal);
            t.material = range.material;
            out.push_back(t);
        }
    return out;
}

TEST(Cornell, TriangleCountAndBounds) {
    const Scene scene = vct::makeCornellBox();
    EXPECT_EQ(scene.name, "cornell");
    EXPECT_TRUE(scene.sourcePath.empty());
    EXPECT_EQ(scene.triangleCount(), 34u);  // 5 walls × 2 + 2 boxes × 12
    EXPECT_EQ(scene.report.sourceTriangles, 34u);
    EXPECT_EQ(scene.report.degenerateTriangles, 0u);
    EXPECT_EQ(scene.report.repairedNormals, 0u);

    EXPECT_NEAR(scene.worldBounds.min.x, -1.0, 1e-6);
    EXPECT_NEAR(scene.worldBounds.min.y, 0.0, 1e-6);
    EXPECT_NEAR(scene.worldBounds.min.z, -1.0, 1e-6);
    EXPECT_NEAR(scene.worldBounds.max.x, 1.0, 1e-6);
    EXPECT_NEAR(scene.worldBounds.max.y, 2.0, 1e-6);
    EXPECT_NEAR(scene.worldBounds.max.z, 1.0, 1e-6);

    // Origin at the bounds centre, vertex positions relative to it.
    EXPECT_NEAR(scene.origin.x, 0.0, 1e-12);
    EXPECT_NEAR(scene.origin.y, 1.0, 1e-12);
    EXPECT_NEAR(scene.origin.z, 0.0, 1e-12);
    glm::vec3 lo(1e9f), hi(-1e9f);
    for (const vct::Vertex& v : scene.vertices) {
        lo = glm::min(lo, v.position);
        hi = glm::max(hi, v.position);
    }
    EXPECT_NEAR(lo.y, -1.0f, 1e-6f);
    EXPECT_NEAR(hi.y, 1.0f, 1e-6f);
    EXPECT_NEAR(lo.x, -1.0f, 1e-6f);
    EXPECT_NEAR(hi.z, 1.0f, 1e-6f);
    const vct::Bounds local = scene.localBounds();
    EXPECT_NEAR(local.min.y, -1.0, 1e-12);
    EXPECT_NEAR(local.max.y, 1.0, 1e-12);
}

TEST(Cornell, NormalsAreUnitAndMatchTheWinding) {
    const Scene scene = vct::makeCornellBox();
    for (const vct::Vertex& v : scene.vertices) EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-6f);
    for (const Triangle& t : triangles(scene))
        EXPECT_NEAR(glm::dot(t.faceNormal, t.vertexNormal), 1.0, 1e-6)
            << "counter-clockwise winding must face the same way as the vertex normal";
}

TEST(Cornell, WallsFaceInwardBoxesOutward) {
    const Scene scene = vct::makeCornellBox();
    int floor = 0, ceiling = 0, back = 0, left = 0, right = 0, boxFaces = 0;
    for (const Triangle& t : triangles(scene)) {
        const glm::dvec3 centroid = (t.a + t.b + t.c) / 3.0;
        const glm::dvec3 n = t.vertexNormal;
        if (std::abs(centroid.y) < 1e-9 && glm::length(t.b - t.a) > 1.5) {
            ++floor;
            EXPECT_NEAR(n.y, 1.0, 1e-9);
        } else if (std::abs(centroid.y - 2.0) < 1e-9) {
            ++ceiling;
            EXPECT_NEAR(n.y, -1.0, 1e-9);
        } else if (std::abs(centroid.z + 1.0) < 1e-9) {
            ++back;
            EXPECT_NEAR(n.z, 1.0, 1e-9);
        } else if (std::abs(centroid.x + 1.0) < 1e-9) {
            ++left;
            EXPECT_NEAR(n.x, 1.0, 1e-9);
            EXPECT_EQ(scene.materials[t.material].name, "red");
        } else if (std::abs(centroid.x - 1.0) < 1e-9) {
            ++right;
            EXPECT_NEAR(n.x, -1.0, 1e-9);
            EXPECT_EQ(scene.materials[t.material].name, "green");
        } else {
            ++boxFaces;
            // A box face (outwardness is checked per box below); bottom faces face down.
            if (centroid.y < 1e-6) {
                EXPECT_NEAR(n.y, -1.0, 1e-6);
            }
        }
    }
    EXPECT_EQ(floor, 2);
    EXPECT_EQ(ceiling, 2);
    EXPECT_EQ(back, 2);
    EXPECT_EQ(left, 2);
    EXPECT_EQ(right, 2);
    EXPECT_EQ(boxFaces, 24);
}

TEST(Cornell, BoxesAreClosedRotatedAndInsideTheRoom) {
    const Scene scene = vct::makeCornellBox();
    // Box triangles: not on a wall plane. Group by height of their top: 0.6 (short), 1.2 (tall).
    std::map<int, std::vector<Triangle>> boxes;
    for (const Triangle& t : triangles(scene)) {
        const glm::dvec3 centroid = (t.a + t.b + t.c) / 3.0;
        const bool wall = std::abs(std::abs(centroid.x) - 1.0) < 1e-9 ||
                          std::abs(centroid.z + 1.0) < 1e-9 ||
                          std::abs(centroid.y - 2.0) < 1e-9 ||
                          (std::abs(centroid.y) < 1e-9 && glm::length(t.b - t.a) > 1.5);
        if (wall) continue;
        boxes[centroid.x > 0.0 ? 0 : 1].push_back(t);
    }
    ASSERT_EQ(boxes[0].size(), 12u);
    ASSERT_EQ(boxes[1].size(), 12u);
    const double expectedHeight[2] = {0.6, 1.2};
    const glm::dvec2 expectedCentre[2] = {{0.35, 0.3}, {-0.35, -0.3}};
    const double expectedAngle[2] = {-17.0, 17.0};
    for (int b = 0; b < 2; ++b) {
        glm::dvec3 lo(1e9), hi(-1e9), sum(0.0);
        double outward = 0.0;
        glm::dvec3 sumNormalArea(0.0);
        for (const Triangle& t : boxes[b]) {
            for (const glm::dvec3& p : {t.a, t.b, t.c}) {
                lo = glm::min(lo, p);
                hi = glm::max(hi, p);
                sum += p;
            }
            sumNormalArea += glm::cross(t.b - t.a, t.c - t.a);
        }
        const glm::dvec3 centre = sum / 36.0;
        for (const Triangle& t : boxes[b]) {
            const glm::dvec3 centroid = (t.a + t.b + t.c) / 3.0;
            outward += glm::dot(t.vertexNormal, centroid - centre) > 0.0 ? 1.0 : 0.0;
        }
        EXPECT_EQ(outward, 12.0) << "box " << b << ": every face must point outward";
        EXPECT_NEAR(glm::length(sumNormalArea), 0.0, 1e-6) << "box " << b << " must be closed";
        EXPECT_NEAR(lo.y, 0.0, 1e-6);
        EXPECT_NEAR(hi.y, expectedHeight[b], 1e-6);
        EXPECT_NEAR(centre.x, expectedCentre[b].x, 1e-6);
        EXPECT_NEAR(centre.z, expectedCentre[b].y, 1e-6);
        EXPECT_GT(lo.x, -1.0);
        EXPECT_LT(hi.x, 1.0);
        EXPECT_GT(lo.z, -1.0);
        EXPECT_LT(hi.z, 1.0);
        // Rotation: the box's x extent is 0.6·(cos a + sin a) instead of 0.6.
        const double a = glm::radians(std::abs(expectedAngle[b]));
        EXPECT_NEAR(hi.x - lo.x, 0.6 * (std::cos(a) + std::sin(a)), 1e-6);
        // Sign of the rotation: a +x-facing side normal turns towards −z for a positive angle
        // (right-handed rotation about +y).
        for (const Triangle& t : boxes[b])
            if (std::abs(t.vertexNormal.y) < 1e-6 && t.vertexNormal.x > 0.5) {
                const double sign = expectedAngle[b] > 0 ? -1.0 : 1.0;  // see above
                EXPECT_NEAR(t.vertexNormal.z, sign * std::sin(a), 1e-6);
            }
    }
}

TEST(Cornell, Materials) {
    const Scene scene = vct::makeCornellBox();
    const vct::Material& red = materialNamed(scene, "red");
    const vct::Material& green = materialNamed(scene, "green");
    const vct::Material& white = materialNamed(scene, "white");
    EXPECT_FLOAT_EQ(red.baseColor.x, 0.63f);
    EXPECT_FLOAT_EQ(red.baseColor.y, 0.065f);
    EXPECT_FLOAT_EQ(red.baseColor.z, 0.05f);
    EXPECT_FLOAT_EQ(green.baseColor.x, 0.14f);
    EXPECT_FLOAT_EQ(green.baseColor.y, 0.45f);
    EXPECT_FLOAT_EQ(green.baseColor.z, 0.091f);
    EXPECT_FLOAT_EQ(white.baseColor.x, 0.725f);
    EXPECT_FLOAT_EQ(white.baseColor.y, 0.725f);
    EXPECT_FLOAT_EQ(white.baseColor.z, 0.725f);
    for (const vct::Material& m : scene.materials) {
        EXPECT_EQ(m.baseColorTexture, -1);
        EXPECT_EQ(m.alphaMode, vct::AlphaMode::Opaque);
        EXPECT_EQ(m.emissive, glm::vec3(0.0f));
    }
    EXPECT_TRUE(scene.textures.empty());
    // Draw ranges: one per material, in material order, covering all indices once.
    std::uint32_t next = 0;
    for (std::size_t i = 0; i < scene.drawRanges.size(); ++i) {
        EXPECT_EQ(scene.drawRanges[i].firstIndex, next);
        if (i > 0) {
            EXPECT_GT(scene.drawRanges[i].material, scene.drawRanges[i - 1].material);
        }
        next += scene.drawRanges[i].indexCount;
    }
    EXPECT_EQ(next, scene.indices.size());
    EXPECT_EQ(scene.drawRanges.size(), 3u);
}

TEST(Cornell, SpotLightCameraExposure) {
    const Scene scene = vct::makeCornellBox();
    ASSERT_EQ(scene.lights.size(), 1u);
    const vct::Light& light = scene.lights[0];
    EXPECT_EQ(light.type, vct::LightType::Spot);
    EXPECT_EQ(light.position, glm::dvec3(0.0, 1.95, 0.0));
    EXPECT_EQ(light.direction, glm::dvec3(0.0, -1.0, 0.0));
    EXPECT_EQ(light.color, glm::dvec3(1.0));
    EXPECT_DOUBLE_EQ(light.intensity, 8.0);
    EXPECT_DOUBLE_EQ(light.innerAngleDeg, 50.0);
    EXPECT_DOUBLE_EQ(light.outerAngleDeg, 70.0);
    EXPECT_NO_THROW(vct::validateLight(light, "cornell spot"));
    EXPECT_NE(vct::describe(light).find("spot"), std::string::npos);

    // It lights the floor below it fully, and nothing above its own height (the ceiling).
    const double cosToCorner = 1.95 / std::sqrt(1.95 * 1.95 + 2.0);
    EXPECT_GT(vct::spotFalloff(cosToCorner, 50.0, 70.0), 0.0) << "floor corners get some light";
    EXPECT_DOUBLE_EQ(vct::spotFalloff(1.0, 50.0, 70.0), 1.0);
    EXPECT_DOUBLE_EQ(vct::spotFalloff(std::cos(glm::radians(95.0)), 50.0, 70.0), 0.0);

    // Floor under the light: E = 8 / 1.95², L = 0.725/π · E ≈ 0.49; with the exposure it lands
    // in [0.6, 0.8].
    const double radiance = 0.725 / M_PI * 8.0 / (1.95 * 1.95);
    const double exposed = radiance * std::exp2(scene.exposureEV);
    EXPECT_GT(exposed, 0.6);
    EXPECT_LT(exposed, 0.8);
    EXPECT_DOUBLE_EQ(scene.exposureEV, 0.5);

    ASSERT_EQ(scene.cameras.size(), 1u);
    const vct::Camera& camera = scene.camera("default");
    EXPECT_EQ(camera.eye, glm::dvec3(0.0, 1.0, 3.9));
    EXPECT_EQ(camera.target, glm::dvec3(0.0, 1.0, 0.0));
    EXPECT_EQ(camera.up, glm::dvec3(0.0, 1.0, 0.0));
    EXPECT_DOUBLE_EQ(camera.fovYDeg, 40.0);
    EXPECT_NO_THROW(vct::validateCamera(camera));
    // The whole opening (z = 1, x,y ∈ [-1,1]×[0,2]) is inside the 40° field of view.
    const double halfHeight = std::tan(glm::radians(20.0)) * (3.9 - 1.0);
    EXPECT_GT(halfHeight, 1.0);
}

TEST(Cornell, LoadSceneAndUnknownCameraPreset) {
    const Scene scene = vct::loadScene("cornell");
    EXPECT_EQ(scene.triangleCount(), 34u);
    try {
        scene.camera("top");
        FAIL() << "expected vct::Error";
    } catch (const vct::Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("'top'"), std::string::npos) << message;
        EXPECT_NE(message.find("'default'"), std::string::npos) << message;
    }
}

}  // namespace
