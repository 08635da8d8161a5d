#pragma once
// Small models written by tests: OBJ files of axis-aligned quads and boxes with one material each.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace vct::test {

struct ObjMaterial {
    std::string name;
    glm::vec3 albedo{0.5f};
    glm::vec3 emission{0.0f};  // Le, W/(m²·sr)
};

// Accumulates triangles per material and writes model.obj + model.mtl.
class ObjWriter {
public:
    void material(const std::string& name, glm::vec3 albedo, glm::vec3 emission = glm::vec3(0.0f)) {
        materials_.push_back({name, albedo, emission});
        use(name);
    }
    void use(const std::string& name) { body_ += "usemtl " + name + "\n"; }
    void triangle(glm::vec3 a, glm::vec3 b, glm::vec3 c) {
        for (glm::vec3 v : {a, b, c}) vertices_.push_back(v);
        const std::size_t n = vertices_.size();
        body_ += "f " + std::to_string(n - 2) + " " + std::to_string(n - 1) + " " + std::to_string(n) + "\n";
    }
    void quad(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) {
        triangle(a, b, c);
        triangle(a, c, d);
    }
    // Horizontal square at height y, half-size h, centred on (cx, cz), facing +y.
    void floor(float y, float h, float cx = 0, float cz = 0) {
        quad({cx - h, y, cz + h}, {cx + h, y, cz + h}, {cx + h, y, cz - h}, {cx - h, y, cz - h});
    }
    // Axis-aligned closed box.
    void box(glm::vec3 lo, glm::vec3 hi) {
        const glm::vec3 c[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z},
                                {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
        const int faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 4, 7, 3}, {1, 2, 6, 5}, {0, 1, 5, 4}, {3, 7, 6, 2}};
        for (const auto& f : faces) quad(c[f[0]], c[f[1]], c[f[2]], c[f[3]]);
    }
    std::filesystem::path write(const std::filesystem::path& dir, const std::string& name = "model") const {
        std::ofstream mtl(dir / (name + ".mtl"));
        for (const auto& m : materials_) {
            mtl << "newmtl " << m.name << "\nKd " << m.albedo.x << " " << m.albedo.y << " " << m.albedo.z << "\n";
            if (m.emission != glm::vec3(0.0f))
                mtl << "Ke " << m.emission.x << " " << m.emission.y << " " << m.emission.z << "\n";
        }
        const auto path = dir / (name + ".obj");
        std::ofstream obj(path);
        obj << "mtllib " << name << ".mtl\n";
        for (const auto& v : vertices_) obj << "v " << v.x << " " << v.y << " " << v.z << "\n";
        obj << body_;
        return path;
    }

private:
    std::vector<ObjMaterial> materials_;
    std::vector<glm::vec3> vertices_;
    std::string body_;
};

// A closed box ±1 with one material of albedo rho and emission Le, flat-shaded: written with one
// explicit normal per face, so that shading and geometric normals agree and the furnace
// conserves energy exactly. (ObjWriter writes no normals; the loader then smooths them across
// the box's edges.)
inline std::filesystem::path writeFurnace(const std::filesystem::path& dir, float rho, float le) {
    std::ofstream(dir / "furnace.mtl") << "newmtl wall\nKd " << rho << " " << rho << " " << rho << "\nKe " << le << " "
                                       << le << " " << le << "\n";
    std::ofstream obj(dir / "furnace.obj");
    obj << "mtllib furnace.mtl\nusemtl wall\n";
    const glm::vec3 c[8] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                            {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    const int faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 4, 7, 3}, {1, 2, 6, 5}, {0, 1, 5, 4}, {3, 7, 6, 2}};
    for (const glm::vec3& v : c) obj << "v " << v.x << " " << v.y << " " << v.z << "\n";
    for (int f = 0; f < 6; ++f) {
        const glm::vec3 n = glm::normalize(glm::cross(c[faces[f][1]] - c[faces[f][0]], c[faces[f][2]] - c[faces[f][0]]));
        obj << "vn " << n.x << " " << n.y << " " << n.z << "\n";
    }
    for (int f = 0; f < 6; ++f) {
        const int n = f + 1;
        const int* q = faces[f];
        obj << "f " << q[0] + 1 << "//" << n << " " << q[1] + 1 << "//" << n << " " << q[2] + 1 << "//" << n << "\n";
        obj << "f " << q[0] + 1 << "//" << n << " " << q[2] + 1 << "//" << n << " " << q[3] + 1 << "//" << n << "\n";
    }
    return dir / "furnace.obj";
}
// The same furnace with walls of thickness `thickness` (closed slabs outside the box ±1), so that
// each inner face has solid behind it. With thickness 10/246 the grid spans ±(1 + 10/246) and
// at 256³ every inner face lies on a cell face 5 cells in: two cells hold it, one on each side.
inline std::filesystem::path writeThickWalledFurnace(const std::filesystem::path& dir, float rho, float le,
                                                     float thickness) {
    ObjWriter obj;
    obj.material("wall", glm::vec3(rho), glm::vec3(le));
    const float outer = 1.0f + thickness;
    for (int axis = 0; axis < 3; ++axis)
        for (float side : {-1.0f, 1.0f}) {
            glm::vec3 lo(-outer), hi(outer);
            lo[axis] = side < 0.0f ? -outer : 1.0f;
            hi[axis] = side < 0.0f ? -1.0f : outer;
            obj.box(lo, hi);
        }
    return obj.write(dir, "thick_furnace");
}
// A camera inside it, looking at the −z wall (options of vct render and vct reference).
inline const std::string kInsideFurnace = " --eye 0,0,0.5 --target 0,0,-1 --fov 70 --width 24 --height 24 ";

}  // namespace vct::test
