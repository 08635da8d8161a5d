// The built-in Cornell box: metres, y up, interior x ∈ [-1, 1], y ∈ [0, 2], z ∈ [-1, 1], open at
// z = +1 where the camera looks in. Albedos are the usual Cornell-box reflectances; the light is
// a spot just below the ceiling pointing down (the ceiling itself stays in its shadow, so it is
// lit only indirectly — a clear test of the GI).
#include <cmath>

#include "scene/mesh_cleanup.hpp"
#include "scene/scene_loader.hpp"

namespace vct {
namespace {

enum : std::uint32_t { kWhite = 0, kRed = 1, kGreen = 2 };

// Adds the rectangle centre ± halfU·u ± halfV·v, facing `normal` (u, normal unit and
// perpendicular; v = normal × u so that the corners run counter-clockwise seen from the front).
void addQuad(WorldGeometry& g, const glm::dvec3& centre, const glm::dvec3& normal,
             const glm::dvec3& u, double halfU, double halfV, std::uint32_t material) {
    const glm::dvec3 v = glm::cross(normal, u);
    const auto first = static_cast<std::uint32_t>(g.positions.size());
    const glm::dvec2 corners[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (const glm::dvec2& c : corners) {
        g.positions.push_back(centre + c.x * halfU * u + c.y * halfV * v);
        g.normals.push_back(normal);
        g.uvs.push_back({0.5 * (c.x + 1.0), 0.5 * (1.0 - c.y)});
    }
    for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) g.indices.push_back(first + i);
    g.triangleMaterials.push_back(material);
    g.triangleMaterials.push_back(material);
}

// A closed box (6 faces, outward normals) resting at `centre`, rotated by `angleDeg` about y.
void addBox(WorldGeometry& g, const glm::dvec3& centre, const glm::dvec3& halfSize,
            double angleDeg, std::uint32_t material) {
    const double a = glm::radians(angleDeg);
    // Right-handed rotation about +y: x' = x cos a + z sin a, z' = −x sin a + z cos a.
    const glm::dvec3 axes[3] = {{std::cos(a), 0.0, -std::sin(a)},
                                {0.0, 1.0, 0.0},
                                {std::sin(a), 0.0, std::cos(a)}};
    for (int axis = 0; axis < 3; ++axis) {
        const int uAxis = (axis + 1) % 3, vAxis = (axis + 2) % 3;
        for (double sign : {1.0, -1.0}) {
            const glm::dvec3 normal = sign * axes[axis];
            addQuad(g, centre + sign * halfSize[axis] * axes[axis], normal, axes[uAxis],
                    halfSize[uAxis], halfSize[vAxis], material);
        }
    }
}

}  // namespace

Scene makeCornellBox() {
    Scene scene;
    scene.name = "cornell";

    auto material = [](const char* name, glm::vec3 albedo) {
        Material m;
        m.name = name;
        m.baseColor = albedo;
        return m;
    };
    scene.materials = {material("white", {0.725f, 0.725f, 0.725f}),
                       material("red", {0.63f, 0.065f, 0.05f}),
                       material("green", {0.14f, 0.45f, 0.091f})};

    WorldGeometry g;
    g.parts.push_back({"cornell box", 0, 0});
    const glm::dvec3 X{1, 0, 0}, Y{0, 1, 0}, Z{0, 0, 1};
    // Walls, normals pointing into the room.
    addQuad(g, {0, 0, 0}, Y, X, 1.0, 1.0, kWhite);    // floor
    addQuad(g, {0, 2, 0}, -Y, X, 1.0, 1.0, kWhite);   // ceiling
    addQuad(g, {0, 1, -1}, Z, X, 1.0, 1.0, kWhite);   // back wall
    addQuad(g, {-1, 1, 0}, X, Z, 1.0, 1.0, kRed);     // left wall
    addQuad(g, {1, 1, 0}, -X, Z, 1.0, 1.0, kGreen);   // right wall
    // The two blocks, resting on the floor.
    addBox(g, {0.35, 0.3, 0.3}, {0.3, 0.3, 0.3}, -17.0, kWhite);    // short
    addBox(g, {-0.35, 0.6, -0.3}, {0.3, 0.6, 0.3}, 17.0, kWhite);   // tall

    buildSceneGeometry(g, "cornell box", false, scene);

    Light spot;
    spot.type = LightType::Spot;
    spot.position = {0.0, 1.95, 0.0};
    spot.direction = {0.0, -1.0, 0.0};
    spot.color = glm::dvec3(1.0);
    spot.intensity = 8.0;  // W/sr: E on the floor below = 8 / 1.95² ≈ 2.1 W/m²
    spot.innerAngleDeg = 50.0;
    spot.outerAngleDeg = 70.0;
    scene.lights = {spot};

    Camera camera;
    camera.name = "default";
    camera.eye = {0.0, 1.0, 3.9};
    camera.target = {0.0, 1.0, 0.0};
    camera.up = {0.0, 1.0, 0.0};
    camera.fovYDeg = 40.0;
    scene.cameras = {camera};

    // The floor under the light reflects L = 0.725/π · 2.1 ≈ 0.49 W/(m²·sr); 2^0.5 brings it to
    // ≈ 0.7 before tone mapping.
    scene.exposureEV = 0.5;
    return scene;
}

}  // namespace vct
