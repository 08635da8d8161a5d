// Scene loading: `--scene` values, the Assimp model importer (geometry, cameras, lights; the
// materials are in material_import.cpp, the clean-up in mesh_cleanup.cpp) and the asset search
// path.
#include "scene/scene_loader.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <unordered_map>
#include <unordered_set>

#include <assimp/DefaultLogger.hpp>
#include <assimp/Importer.hpp>
#include <assimp/LogStream.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/version.h>

#include "core/error.hpp"
#include "core/file_extension.hpp"
#include "core/log.hpp"
#include "core/vector_text.hpp"
#include "scene/file_precheck.hpp"
#include "scene/gltf_json.hpp"
#include "scene/gltf_resources.hpp"
#include "scene/gltf_support.hpp"
#include "scene/material_import.hpp"
#include "scene/mesh_cleanup.hpp"

namespace fs = std::filesystem;

namespace vct {

const Camera& Scene::camera(const std::string& presetName) const {
    for (const Camera& c : cameras)
        if (c.name == presetName) return c;
    std::string available;
    for (const Camera& c : cameras) available += (available.empty() ? "'" : ", '") + c.name + "'";
    fail("camera preset '", presetName, "' not found in scene '", name, "'; available: ",
         available.empty() ? std::string("none") : available);
}

namespace {

// ------------------------------------------------------------------------------------------------
// Small helpers

glm::dmat4 toDouble(const aiMatrix4x4& m) {
    // aiMatrix4x4 is row-major (a1..a4 = first row); glm is column-major: r[column][row].
    glm::dmat4 r;
    for (int row = 0; row < 4; ++row)
        for (int column = 0; column < 4; ++column) r[column][row] = double(m[row][column]);
    return r;
}

glm::dvec3 toDouble(const aiVector3D& v) { return {double(v.x), double(v.y), double(v.z)}; }

glm::dvec3 transformPoint(const glm::dmat4& m, const glm::dvec3& p) {
    return glm::dvec3(m * glm::dvec4(p, 1.0));
}

glm::dvec3 transformDirection(const glm::dmat4& m, const glm::dvec3& d) {
    return glm::dmat3(m) * d;
}

bool isGltf(const fs::path& path) {
    const std::string ext = lowerExtension(path);
    return ext == ".gltf" || ext == ".glb";
}

// Assimp ≥ 5.3 (PR #5055, #4886) fixed two glTF camera bugs present in the 5.2 series that
// Debian 12 ships; we undo whichever the linked library has.
bool assimpAtLeast(unsigned major, unsigned minor) {
    const unsigned ma = aiGetVersionMajor(), mi = aiGetVersionMinor();
    return ma > major || (ma == major && mi >= minor);
}

struct FlatNode {
    const aiNode* node;
    glm::dmat4 world;
};

// Every node with its world transform, accumulated in double, parents before children. Iterative
// (no recursion depth limit) and robust against a node appearing twice in a corrupt tree.
std::vector<FlatNode> flattenNodes(const aiScene& ai) {
    std::vector<FlatNode> out;
    if (!ai.mRootNode) return out;
    std::vector<FlatNode> stack{{ai.mRootNode, toDouble(ai.mRootNode->mTransformation)}};
    std::unordered_set<const aiNode*> seen;
    while (!stack.empty()) {
        FlatNode current = stack.back();
        stack.pop_back();
        if (!current.node || !seen.insert(current.node).second) continue;
        out.push_back(current);
        for (unsigned i = current.node->mNumChildren; i-- > 0;) {
            const aiNode* child = current.node->mChildren[i];
            if (child) stack.push_back({child, current.world * toDouble(child->mTransformation)});
        }
    }
    return out;
}

// ------------------------------------------------------------------------------------------------
// Assimp's own warnings: what it repairs or drops (faces with out-of-range indices, material
// libraries it cannot find, unknown materials) it only logs. Nothing may be dropped silently, so
// the messages of one load are collected and, if the load succeeds, passed on as vct warnings.

thread_local std::vector<std::string>* assimpMessages = nullptr;

struct AssimpMessageStream : Assimp::LogStream {
    void write(const char* message) override {
        if (!assimpMessages) return;
        std::string text(message);
        // "Warn,  T0: text\n" → "text"
        if (const auto colon = text.find(": "); colon != std::string::npos && colon < 16) text.erase(0, colon + 2);
        while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
        // Benign: the OBJ reader makes a default object for faces before any "o"/"g" line.
        if (text.find("No object detected to attach a new mesh instance") != std::string::npos) return;
        if (!text.empty() && std::find(assimpMessages->begin(), assimpMessages->end(), text) == assimpMessages->end())
            assimpMessages->push_back(text);
    }
};

class AssimpMessages {
public:
    AssimpMessages() {
        static const bool attached = [] {
            if (Assimp::DefaultLogger::isNullLogger()) Assimp::DefaultLogger::create("", Assimp::Logger::NORMAL, 0);
            return Assimp::DefaultLogger::get()->attachStream(new AssimpMessageStream,
                                                              Assimp::Logger::Warn | Assimp::Logger::Err);
        }();
        (void)attached;
        assimpMessages = &messages_;
    }
    ~AssimpMessages() { assimpMessages = nullptr; }
    void report(const std::string& source) const {
        for (const std::string& m : messages_) logWarn(concat(source, ": ", m));
    }

private:
    std::vector<std::string> messages_;
};

// ------------------------------------------------------------------------------------------------
// Geometry

std::string meshNameOf(const aiMesh& mesh, unsigned meshIndex) {
    return mesh.mName.length > 0 ? std::string(mesh.mName.C_Str()) : concat("mesh ", meshIndex);
}

// Non-finite vertex positions must be found before aiProcess_JoinIdenticalVertices: its
// epsilon comparisons are false for NaN, so it silently merges a NaN vertex into a neighbour
// and the model renders with a wrong triangle instead of failing. So the file is read without
// that step, checked here, and the step applied afterwards.
struct NonFiniteScan {
    std::size_t vertices = 0;           // source vertices with a NaN/Inf position
    std::size_t droppedTriangles = 0;   // triangles removed (counted per instance), sanitize only
};

// How many nodes place each mesh.
std::vector<std::size_t> instanceCounts(const aiScene& ai, const std::vector<FlatNode>& nodes) {
    std::vector<std::size_t> instances(ai.mNumMeshes, 0);
    for (const FlatNode& flat : nodes)
        for (unsigned k = 0; k < flat.node->mNumMeshes; ++k)
            if (flat.node->mMeshes[k] < ai.mNumMeshes) ++instances[flat.node->mMeshes[k]];
    return instances;
}

// Flags the vertices of mesh `m` without a usable position; beyond ±kMaxWorldCoordinate counts
// as non-finite too, as in buildSceneGeometry. `first` names the first one found in the file.
std::vector<char> badVertices(const aiMesh& mesh, unsigned m, std::size_t& count, std::string& first) {
    std::vector<char> bad(mesh.mNumVertices, 0);
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
        if (isUsableCoordinate(toDouble(mesh.mVertices[v]))) continue;
        bad[v] = 1;
        ++count;
        if (first.empty()) first = concat("mesh '", meshNameOf(mesh, m), "' vertex ", v);
    }
    return bad;
}

// Drops the faces that use a bad vertex and parks the bad positions, which no face uses any
// more, at 0. Returns the triangles dropped, counted once per instance of the mesh.
std::size_t dropFacesUsing(aiMesh& mesh, const std::vector<char>& bad, std::size_t instances) {
    auto usesBad = [&](const aiFace& f) {
        for (unsigned c = 0; c < f.mNumIndices; ++c)
            if (f.mIndices[c] < mesh.mNumVertices && bad[f.mIndices[c]]) return true;
        return false;
    };
    unsigned keep = 0;
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) keep += usesBad(mesh.mFaces[f]) ? 0 : 1;
    aiFace* kept = new aiFace[std::max(keep, 1u)];
    std::size_t dropped = 0;
    unsigned k = 0;
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
        aiFace& face = mesh.mFaces[f];
        if (usesBad(face)) {
            if (face.mNumIndices == 3) dropped += instances;
            continue;
        }
        std::swap(kept[k].mNumIndices, face.mNumIndices);
        std::swap(kept[k].mIndices, face.mIndices);
        ++k;
    }
    delete[] mesh.mFaces;
    mesh.mFaces = kept;
    mesh.mNumFaces = keep;
    for (unsigned v = 0; v < mesh.mNumVertices; ++v)
        if (bad[v]) mesh.mVertices[v] = aiVector3D(0.0f, 0.0f, 0.0f);
    return dropped;
}

NonFiniteScan removeNonFinitePositions(aiScene& ai, const std::vector<FlatNode>& nodes,
                                       const std::string& source, bool sanitize) {
    const std::vector<std::size_t> instances = instanceCounts(ai, nodes);
    NonFiniteScan scan;
    std::string first;
    for (unsigned m = 0; m < ai.mNumMeshes; ++m) {
        aiMesh* mesh = ai.mMeshes[m];
        if (!mesh || !mesh->mVertices || instances[m] == 0) continue;
        std::size_t badHere = 0;
        const std::vector<char> bad = badVertices(*mesh, m, badHere, first);
        scan.vertices += badHere;
        if (badHere > 0 && sanitize) scan.droppedTriangles += dropFacesUsing(*mesh, bad, instances[m]);
    }
    if (scan.vertices > 0 && !sanitize) failNonFinitePositions(source, scan.vertices, first);
    if (scan.droppedTriangles > 0)
        warnDroppedNonFiniteTriangles(source, scan.droppedTriangles, scan.vertices);
    return scan;
}

// Assimp's post-processing steps compare positions and normalise normals in float, with
// epsilons and squared lengths that suit a model about one unit in size: at a millionth of that
// JoinIdenticalVertices and GenSmoothNormals merge and split the wrong vertices (triangles
// collapse), and from about 1e10 units a face normal's squared length overflows, so every
// generated normal is zero. For those steps each mesh is therefore brought to a size between 1
// and 2 by a power of two, which scales a float exactly, and afterwards scaled back. Returns the
// exponent applied to each mesh.
void scaleMesh(aiMesh& mesh, int exponent) {
    for (unsigned v = 0; v < mesh.mNumVertices; ++v)
        for (int a = 0; a < 3; ++a) mesh.mVertices[v][a] = std::ldexp(mesh.mVertices[v][a], exponent);
}

std::vector<int> scaleMeshesToUnitSize(aiScene& ai) {
    std::vector<int> exponents(ai.mNumMeshes, 0);
    for (unsigned m = 0; m < ai.mNumMeshes; ++m) {
        aiMesh* mesh = ai.mMeshes[m];
        if (!mesh || !mesh->mVertices) continue;
        float lowest[3] = {INFINITY, INFINITY, INFINITY}, highest[3] = {-INFINITY, -INFINITY, -INFINITY};
        float largest = 0.0f;  // the largest |coordinate|, so that scaling up cannot overflow
        for (unsigned v = 0; v < mesh->mNumVertices; ++v)
            for (int a = 0; a < 3; ++a) {
                const float x = mesh->mVertices[v][a];
                if (!std::isfinite(x)) continue;  // sanitized away later
                lowest[a] = std::min(lowest[a], x);
                highest[a] = std::max(highest[a], x);
                largest = std::max(largest, std::abs(x));
            }
        float size = 0.0f;
        for (int a = 0; a < 3; ++a)
            if (highest[a] >= lowest[a]) size = std::max(size, highest[a] - lowest[a]);
        if (!(size > 0.0f) || !std::isfinite(size)) continue;
        int exponent = -std::ilogb(size);  // size · 2^exponent in [1, 2)
        exponent = std::min(exponent, 100 - std::ilogb(largest));  // keep every coordinate below 2^101
        exponents[m] = exponent;
        scaleMesh(*mesh, exponent);
    }
    return exponents;
}

void undoMeshScales(aiScene& ai, const std::vector<int>& exponents) {
    for (unsigned m = 0; m < ai.mNumMeshes && m < exponents.size(); ++m) {
        aiMesh* mesh = ai.mMeshes[m];
        if (mesh && mesh->mVertices && exponents[m] != 0) scaleMesh(*mesh, -exponents[m]);
    }
}

// A node's world transform as applied to its meshes.
struct InstanceTransform {
    explicit InstanceTransform(const glm::dmat4& nodeWorld)
        : world(nodeWorld),
          normalMatrix(glm::transpose(glm::inverse(glm::dmat3(nodeWorld)))),
          mirrored(glm::determinant(glm::dmat3(nodeWorld)) < 0.0) {}
    glm::dmat4 world;
    glm::dmat3 normalMatrix;
    bool mirrored;  // swap two corners of each triangle to keep counter-clockwise = front
};

struct MeshRef {
    const aiMesh& mesh;
    unsigned index;    // in aiScene::mMeshes
    std::string name;  // for messages
};

MeshRef meshOf(const aiScene& ai, const aiNode& node, unsigned k, const std::string& source) {
    const unsigned meshIndex = node.mMeshes[k];
    if (meshIndex >= ai.mNumMeshes || !ai.mMeshes[meshIndex])
        fail(source, ": node '", node.mName.C_Str(), "' refers to mesh ", meshIndex,
             ", but the file has only ", ai.mNumMeshes, " meshes; the file is corrupt");
    const aiMesh& mesh = *ai.mMeshes[meshIndex];
    return {mesh, meshIndex, meshNameOf(mesh, meshIndex)};
}

// Triangle faces of the mesh; its other faces (points and lines: polygons were triangulated)
// are added to `ignoredPrimitives`.
std::size_t countTriangles(const aiMesh& mesh, std::size_t& ignoredPrimitives) {
    std::size_t triangles = 0;
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
        if (mesh.mFaces[f].mNumIndices == 3)
            ++triangles;
        else
            ++ignoredPrimitives;
    }
    return triangles;
}

// Index in WorldGeometry::positions at which the instance's vertices will start.
std::uint32_t firstVertexFor(const WorldGeometry& g, const aiMesh& mesh, const std::string& source) {
    const std::uint64_t first = g.positions.size();
    if (first + mesh.mNumVertices >= std::numeric_limits<std::uint32_t>::max())
        fail(source, ": the model has more than 4 billion vertices once instanced; vct "
                     "cannot index that many");
    return static_cast<std::uint32_t>(first);
}

// The mesh's Assimp material index; one beyond the file's materials (mNumMaterials) stands for a
// default grey material, with a warning.
std::uint32_t aiMaterialOf(const aiScene& ai, const MeshRef& ref, const std::string& source) {
    const aiMesh& mesh = ref.mesh;
    if (mesh.mMaterialIndex < ai.mNumMaterials) return mesh.mMaterialIndex;
    logWarnOnce(concat("badmaterial:", source, ":", ref.index),
                concat(source, ": mesh '", ref.name, "' refers to material ", mesh.mMaterialIndex,
                       " (the file has ", ai.mNumMaterials, "); using a default grey material"));
    return ai.mNumMaterials;
}

// Scene material indices in order of first use: `used[slot]` is the Assimp material index.
class MaterialSlots {
public:
    explicit MaterialSlots(std::vector<std::uint32_t>& used) : used_(used) {}
    std::uint32_t slotOf(std::uint32_t aiMaterial) {
        auto [slot, inserted] = slots_.emplace(aiMaterial, static_cast<std::uint32_t>(used_.size()));
        if (inserted) used_.push_back(aiMaterial);
        return slot->second;
    }

private:
    std::vector<std::uint32_t>& used_;
    std::unordered_map<std::uint32_t, std::uint32_t> slots_;  // ai index -> scene index
};

// The second UV set and the vertex colours are kept only when some mesh has them (then every
// vertex gets one, 0 or white where its mesh has none).
void appendVertices(const aiMesh& mesh, const InstanceTransform& transform, WorldGeometry& g) {
    const aiVector3D* uvs = mesh.mTextureCoords[0];
    const aiVector3D* uvs1 = mesh.mTextureCoords[1];
    const aiColor4D* colours = mesh.mColors[0];
    const std::size_t before = g.positions.size();
    const bool keepUvs1 = uvs1 || !g.uvs1.empty(), keepColours = colours || !g.colors.empty();
    if (keepUvs1) g.uvs1.resize(before, glm::dvec2(0.0));
    if (keepColours) g.colors.resize(before, glm::vec3(1.0f));
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
        // glTF COLOR_0 is linear RGB(A) and multiplies the base colour. Its alpha is not used:
        // Assimp 5.2 reports alpha 0 for RGB colours, so it cannot be told from a real 0.
        if (keepColours)
            g.colors.push_back(colours ? glm::vec3(colours[v].r, colours[v].g, colours[v].b) : glm::vec3(1.0f));
        if (keepUvs1) g.uvs1.push_back(uvs1 ? glm::dvec2(uvs1[v].x, uvs1[v].y) : glm::dvec2(0.0));
        g.positions.push_back(transformPoint(transform.world, toDouble(mesh.mVertices[v])));
        g.normals.push_back(mesh.mNormals ? transform.normalMatrix * toDouble(mesh.mNormals[v])
                                          : glm::dvec3(0.0));
        // Assimp's convention, kept as is (see Vertex::uv): v = 0 at the bottom of the image
        // for every format (the glTF importer flips glTF's v).
        g.uvs.push_back(uvs ? glm::dvec2(uvs[v].x, uvs[v].y) : glm::dvec2(0.0));
    }
}

void appendTriangles(const MeshRef& ref, std::uint32_t base, bool mirrored, std::uint32_t material,
                     const std::string& source, WorldGeometry& g) {
    const aiMesh& mesh = ref.mesh;
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
        const aiFace& face = mesh.mFaces[f];
        if (face.mNumIndices != 3) continue;
        for (int c = 0; c < 3; ++c)
            if (face.mIndices[c] >= mesh.mNumVertices)
                fail(source, ": mesh '", ref.name, "' face ", f, " uses vertex ", face.mIndices[c],
                     ", but the mesh has only ", mesh.mNumVertices, " vertices; the file is corrupt");
        const std::uint32_t a = face.mIndices[0], b = face.mIndices[1], c = face.mIndices[2];
        g.indices.push_back(base + a);
        g.indices.push_back(base + (mirrored ? c : b));
        g.indices.push_back(base + (mirrored ? b : c));
        g.triangleMaterials.push_back(material);
    }
}

// Says why no triangle reached the scene, as precisely as the file allows.
[[noreturn]] void failNoTriangles(const aiScene& ai, std::size_t droppedEarlier,
                                  std::size_t ignoredPrimitives, const std::string& source) {
    if (ai.mNumMeshes == 0)
        fail(source, ": the model has no triangles (the file contains no meshes; is it a "
                     "valid model file?)");
    if (droppedEarlier > 0)
        fail(source, ": the model has no triangles (all ", droppedEarlier,
             " were dropped for non-finite positions)");
    fail(source, ": the model has no triangles (", ai.mNumMeshes, " meshes, ", ignoredPrimitives,
         " point/line primitives, no triangle faces in the scene graph)");
}

// Every mesh instance of the scene graph, in world space (double), into `g`; `usedMaterials`
// gets the Assimp material index of each scene material that the triangles refer to.
void gatherGeometry(const aiScene& ai, const std::vector<FlatNode>& nodes,
                    const std::string& source, std::size_t droppedEarlier, WorldGeometry& g,
                    std::vector<std::uint32_t>& usedMaterials) {
    MaterialSlots materials(usedMaterials);
    std::size_t ignoredPrimitives = 0;
    for (const FlatNode& flat : nodes) {
        const InstanceTransform transform(flat.world);
        for (unsigned k = 0; k < flat.node->mNumMeshes; ++k) {
            const MeshRef ref = meshOf(ai, *flat.node, k, source);
            if (countTriangles(ref.mesh, ignoredPrimitives) == 0) continue;
            if (!ref.mesh.mVertices)
                fail(source, ": mesh '", ref.name, "' has faces but no vertex positions");
            const std::uint32_t first = firstVertexFor(g, ref.mesh, source);
            const std::uint32_t material = materials.slotOf(aiMaterialOf(ai, ref, source));
            g.parts.push_back({ref.name, ref.index, first});
            appendVertices(ref.mesh, transform, g);
            appendTriangles(ref, first, transform.mirrored, material, source, g);
        }
    }
    if (ignoredPrimitives > 0)
        logWarn(concat(source, ": ignored ", ignoredPrimitives,
                       " point and line primitives (only triangles are rendered)"));
    if (g.triangleCount() == 0) failNoTriangles(ai, droppedEarlier, ignoredPrimitives, source);
}

// ------------------------------------------------------------------------------------------------
// Cameras and lights

Camera defaultCamera(const Bounds& bounds) {
    // Looks at the centre from the +z side, a little above, far enough for the bounding sphere
    // to fit a 45° field of view.
    Camera camera;
    camera.name = "default";
    camera.fovYDeg = 45.0;
    const double radius = 0.5 * glm::length(bounds.size());
    const double distance =
        radius > 0.0 ? radius / std::sin(glm::radians(0.5 * camera.fovYDeg)) : 1.0;
    camera.target = bounds.centre();
    camera.eye = camera.target + distance * glm::normalize(glm::dvec3(0.0, 0.25, 1.0));
    camera.up = {0.0, 1.0, 0.0};
    return camera;
}

Light defaultSun() {
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(glm::dvec3(-0.3, -1.0, -0.2));
    sun.irradiance = 3.0;
    return sun;
}

const glm::dmat4* findNode(const std::unordered_map<std::string, glm::dmat4>& byName,
                           const aiString& name) {
    auto it = byName.find(name.C_Str());
    return it == byName.end() ? nullptr : &it->second;
}

// Vertical field of view in degrees. glTF stores yfov; assimp hands over a "horizontal" angle:
// 5.2 computes yfov·aspect (wrong, but exactly invertible), ≥ 5.3 the true full horizontal angle
// 2·atan(tan(yfov/2)·aspect). Other formats: the full horizontal angle.
double verticalFovDeg(const aiCamera& c, bool gltf) {
    const double hfov = c.mHorizontalFOV;
    const double aspect = c.mAspect > 0.0f ? double(c.mAspect) : 0.0;
    double fovY = hfov;
    if (aspect > 0.0) {
        if (gltf && !assimpAtLeast(5, 3))
            fovY = hfov / aspect;
        else
            fovY = 2.0 * std::atan(std::tan(0.5 * hfov) / aspect);
    }
    return glm::degrees(fovY);
}

void importCameras(const aiScene& ai, const std::unordered_map<std::string, glm::dmat4>& byName,
                   bool gltf, const std::string& source, Scene& scene) {
    const double targetDistance = std::max(0.5 * glm::length(scene.worldBounds.size()), 1e-6);
    std::unordered_set<std::string> names;
    for (unsigned i = 0; i < ai.mNumCameras; ++i) {
        const aiCamera* c = ai.mCameras[i];
        if (!c) continue;
        Camera camera;
        const std::string baseName =
            c->mName.length > 0 ? std::string(c->mName.C_Str()) : concat("camera ", i);
        camera.name = baseName;
        for (int n = 2; !names.insert(camera.name).second; ++n)
            camera.name = concat(baseName, " (", n, ")");  // presets need unique names
        if (c->mHorizontalFOV <= 0.0f && c->mOrthographicWidth > 0.0f) {
            logWarn(concat(source, ": camera '", camera.name,
                           "' is orthographic, which vct does not support; skipped"));
            continue;
        }
        const glm::dmat4* node = findNode(byName, c->mName);
        if (!node)
            logWarn(concat(source, ": camera '", camera.name,
                           "' has no node of the same name; using it untransformed"));
        const glm::dmat4 world = node ? *node : glm::dmat4(1.0);
        // glTF cameras sit at their node's origin; assimp < 5.3 also copies the node's
        // translation into mPosition (applying the node would then count it twice).
        const glm::dvec3 local = gltf ? glm::dvec3(0.0) : toDouble(c->mPosition);
        camera.eye = transformPoint(world, local);
        const glm::dvec3 forward = transformDirection(world, toDouble(c->mLookAt));
        camera.target = camera.eye + targetDistance * glm::normalize(forward);
        camera.up = glm::normalize(transformDirection(world, toDouble(c->mUp)));
        camera.fovYDeg = verticalFovDeg(*c, gltf);
        try {
            validateCamera(camera);
        } catch (const Error& e) {
            logWarn(concat(source, ": skipped a camera: ", e.what()));
            continue;
        }
        scene.cameras.push_back(camera);
    }
}

// A spot or point light's intensity: the file's scalar divided by a pure quadratic attenuation factor; any
// other attenuation is replaced by the inverse-square law, with a warning.
double inverseSquareIntensity(const aiLight& l, double scalar, const std::string& what) {
    const double a0 = l.mAttenuationConstant, a1 = l.mAttenuationLinear, a2 = l.mAttenuationQuadratic;
    if (a0 == 0.0 && a1 == 0.0 && a2 > 0.0 && std::isfinite(a2)) return scalar / a2;
    logWarnOnce(what + ":attenuation", concat(what, ": attenuation 1/(", a0, " + ", a1, "·d + ", a2,
                                              "·d²) replaced by the inverse-square law 1/d²"));
    return scalar;
}

// Cone half-angles in degrees, the outer one capped just below 90° and the inner one at most
// the outer one.
void setConeAngles(const aiLight& l, const std::string& what, Light& light) {
    light.innerAngleDeg = glm::degrees(double(l.mAngleInnerCone));
    light.outerAngleDeg = glm::degrees(double(l.mAngleOuterCone));
    if (light.outerAngleDeg >= 90.0) {
        logWarn(concat(what, ": outer cone angle ", light.outerAngleDeg, "° capped to 89.9°"));
        light.outerAngleDeg = 89.9;
    }
    light.innerAngleDeg = std::min(light.innerAngleDeg, light.outerAngleDeg);
}

// Lights. vct has directional lights (irradiance, W/m²), spot and point lights (intensity, W/sr,
// with inverse-square falloff). Conversion from what assimp delivers:
//   * assimp multiplies glTF's `intensity` into the colour; we split it again into a scalar
//     (the largest RGB component) and a tint (colour / scalar, so max component = 1).
//   * glTF's photometric values are taken as the matching radiometric ones: lux → W/m²,
//     candela → W/sr (no 683 lm/W factor). This keeps the file's light balance; the scene's
//     exposureEV is derived from the brightest light, so the picture is exposed either way.
//   * KHR_lights_punctual spots and points fall off as 1/d² (assimp: quadratic attenuation 1), exactly
//     like ours; a pure quadratic factor q ≠ 1 divides the intensity, any constant or linear
//     term (other formats) is replaced by the inverse-square law with a warning. glTF `range`
//     is ignored.
//   * glTF cone angles are half-angles in radians (assimp passes them through); we use them as
//     half-angles in degrees, the outer one capped just below 90°.
//   * ambient and area lights have no vct equivalent: skipped with a warning.
void importLights(const aiScene& ai, const std::unordered_map<std::string, glm::dmat4>& byName,
                  bool gltf, const std::string& source, Scene& scene) {
    for (unsigned i = 0; i < ai.mNumLights; ++i) {
        const aiLight* l = ai.mLights[i];
        if (!l) continue;
        const std::string name =
            l->mName.length > 0 ? std::string(l->mName.C_Str()) : concat("light ", i);
        const std::string what = concat(source, ": light '", name, "'");
        if (l->mType != aiLightSource_DIRECTIONAL && l->mType != aiLightSource_SPOT &&
            l->mType != aiLightSource_POINT) {
            logWarn(concat(what, " is an ambient or area light, which vct does not "
                                 "support (only directional, spot and point lights); skipped"));
            continue;
        }
        const glm::dmat4* node = findNode(byName, l->mName);
        const glm::dmat4 world = node ? *node : glm::dmat4(1.0);

        Light light;
        const glm::dvec3 colour{l->mColorDiffuse.r, l->mColorDiffuse.g, l->mColorDiffuse.b};
        const double scalar = std::max({colour.x, colour.y, colour.z});
        if (!(scalar > 0.0) || !std::isfinite(scalar)) {
            logWarn(concat(what, " has colour × intensity (", colour.x, ", ", colour.y, ", ",
                           colour.z, "), so it emits nothing; skipped"));
            continue;
        }
        light.color = colour / scalar;
        light.direction = transformDirection(world, toDouble(l->mDirection));
        if (glm::length(light.direction) > 0.0) light.direction = glm::normalize(light.direction);

        if (l->mType == aiLightSource_DIRECTIONAL) {
            light.type = LightType::Directional;
            light.irradiance = scalar;
        } else {
            light.type = l->mType == aiLightSource_SPOT ? LightType::Spot : LightType::Point;
            light.position = transformPoint(world, gltf ? glm::dvec3(0.0) : toDouble(l->mPosition));
            light.intensity = inverseSquareIntensity(*l, scalar, what);
            if (light.type == LightType::Spot) setConeAngles(*l, what, light);
        }
        try {
            validateLight(light, what);
        } catch (const Error& e) {
            logWarn(concat("skipped a light: ", e.what()));
            continue;
        }
        scene.lights.push_back(light);
    }
}

// An exposure that maps a surface of albedo 0.5 facing the brightest light to ≈ 0.8.
double exposureFor(const std::vector<Light>& lights, const Bounds& bounds) {
    double brightest = 0.0;
    for (const Light& light : lights) {
        const double tint = std::max({light.color.x, light.color.y, light.color.z});
        if (light.type == LightType::Directional) {
            brightest = std::max(brightest, light.irradiance * tint);
        } else {
            const double d = std::max(glm::length(light.position - bounds.centre()),
                                      1e-3 * glm::length(bounds.size()));
            if (d > 0.0) brightest = std::max(brightest, light.intensity * tint / (d * d));
        }
    }
    if (!(brightest > 0.0) || !std::isfinite(brightest)) return 0.0;
    const double radiance = 0.5 / std::numbers::pi * brightest;
    return std::round(2.0 * std::log2(0.8 / radiance)) / 2.0;  // nearest half stop
}

// ------------------------------------------------------------------------------------------------
// The model file as a whole

void checkModelPath(const fs::path& path) {
    std::error_code ec;
    if (!fs::exists(path, ec))
        fail("model file '", path.string(),
             "' not found; check the path, or use --scene cornell|sponza");
    if (fs::is_directory(path, ec))
        fail("model path '", path.string(),
             "' is a folder, not a model file; give the .gltf/.glb/.obj file inside it");
}

// Reads the file with Assimp (which keeps the result): triangulated, meshes split by primitive
// type (so that points and lines can be counted and skipped); then, once non-finite positions
// are dealt with (see NonFiniteScan), identical vertices shared and normals generated where the
// file has none, each mesh scaled to unit size meanwhile (scaleMeshesToUnitSize). Node transforms are applied later, in double precision (not
// aiProcess_PreTransformVertices). Assimp's own warnings are passed on once the read succeeded.
const aiScene& readModel(Assimp::Importer& importer, const std::string& source, bool sanitize,
                         NonFiniteScan& nonFinite) {
    // Generated normals are smoothed only across edges flatter than 80°: a box made of shared
    // vertices keeps flat faces instead of diagonal corner normals that light it from inside.
    importer.SetPropertyFloat(AI_CONFIG_PP_GSN_MAX_SMOOTHING_ANGLE, 80.0f);
    const aiScene* ai = nullptr;
    const AssimpMessages assimpLog;
    try {
        ai = importer.ReadFile(source, aiProcess_Triangulate | aiProcess_SortByPType);
    } catch (const std::exception& e) {
        fail("cannot read model '", source, "': ", e.what());
    }
    if (!ai) {
        // The format hint only where the format is what Assimp did not recognise: a glTF file
        // with a missing buffer is a glTF file.
        const std::string reason = importer.GetErrorString();
        const bool unknownFormat = reason.find("No suitable reader") != std::string::npos;
        fail("cannot read model '", source, "': ", reason,
             unknownFormat ? " (a glTF 2.0, GLB or OBJ file is expected)" : "");
    }
    if (!ai->mRootNode)
        fail("cannot read model '", source, "': the file has no scene graph");

    nonFinite =
        removeNonFinitePositions(*const_cast<aiScene*>(ai), flattenNodes(*ai), source, sanitize);
    const std::vector<int> exponents = scaleMeshesToUnitSize(*const_cast<aiScene*>(ai));
    try {
        ai = importer.ApplyPostProcessing(aiProcess_JoinIdenticalVertices |
                                          aiProcess_GenSmoothNormals);
    } catch (const std::exception& e) {
        fail("cannot read model '", source, "': ", e.what());
    }
    if (!ai || !ai->mRootNode)
        fail("cannot read model '", source, "': ", importer.GetErrorString());
    undoMeshScales(*const_cast<aiScene*>(ai), exponents);
    assimpLog.report(source);
    return *ai;
}

// Triangles and materials into the scene, with the triangles that the early non-finite check
// dropped added to the counts.
void importGeometry(const aiScene& ai, const std::vector<FlatNode>& nodes, const fs::path& path,
                    const NonFiniteScan& nonFinite, const std::vector<GltfMaterialExtras>& extras, bool sanitize,
                    Scene& scene) {
    const std::string source = path.string();
    WorldGeometry geometry;
    std::vector<std::uint32_t> usedMaterials;
    gatherGeometry(ai, nodes, source, nonFinite.droppedTriangles, geometry, usedMaterials);
    importMaterials(ai, usedMaterials, extras, path, scene);
    buildSceneGeometry(geometry, source, sanitize, scene);
    scene.report.sourceTriangles += nonFinite.droppedTriangles;
    scene.report.droppedTriangles += nonFinite.droppedTriangles;
    scene.report.nonFinitePositions += nonFinite.vertices;
}

// The file's cameras and lights, placed by the node of the same name; a default camera and sun
// derived from the bounds when it has none.
void importCamerasAndLights(const aiScene& ai, const std::vector<FlatNode>& nodes, bool gltf,
                            const std::string& source, Scene& scene) {
    std::unordered_map<std::string, glm::dmat4> byName;  // first node of each name
    for (const FlatNode& n : nodes) byName.emplace(n.node->mName.C_Str(), n.world);
    importCameras(ai, byName, gltf, source, scene);
    if (scene.cameras.empty()) scene.cameras.push_back(defaultCamera(scene.worldBounds));

    importLights(ai, byName, gltf, source, scene);
    if (scene.lights.empty()) {
        scene.lights.push_back(defaultSun());
        scene.exposureEV = 0.0;
    } else {
        scene.exposureEV = exposureFor(scene.lights, scene.worldBounds);
    }
}

}  // namespace

// ------------------------------------------------------------------------------------------------

Scene loadModelFile(const fs::path& path, const LoadOptions& options) {
    checkModelPath(path);
    const std::string source = path.string();
    precheckModelFile(path);
    const std::optional<nlohmann::json> gltf = readGltfJson(path);
    if (gltf) {
        checkRequiredGltfExtensions(*gltf, source);
        checkGltfResources(*gltf, path);
    }

    Assimp::Importer importer;
    NonFiniteScan nonFinite;
    const aiScene& ai = readModel(importer, source, options.sanitize, nonFinite);
    const std::vector<FlatNode> nodes = flattenNodes(ai);
    const std::vector<GltfMaterialExtras> extras = gltf ? gltfMaterialExtras(*gltf, ai, source)
                                                        : std::vector<GltfMaterialExtras>{};

    Scene scene;
    scene.name = path.filename().string();
    std::error_code ec;
    scene.sourcePath = fs::absolute(path, ec).lexically_normal().string();
    if (scene.sourcePath.empty()) scene.sourcePath = source;

    importGeometry(ai, nodes, path, nonFinite, extras, options.sanitize, scene);
    importCamerasAndLights(ai, nodes, isGltf(path), source, scene);
    if (gltf) reportUnsupportedGltfFeatures(*gltf, source, scene.report);
    return scene;
}

// ------------------------------------------------------------------------------------------------
// Asset search path

namespace {

std::vector<fs::path> assetRoots() {
    std::vector<fs::path> roots;
    if (const char* env = std::getenv("VCT_ASSET_DIR"); env && *env) roots.emplace_back(env);
    roots.emplace_back("assets");
    roots.emplace_back(fs::path(VCT_SOURCE_DIR) / "assets");
    roots.emplace_back(fs::path("..") / "shared" / "assets");
    roots.emplace_back(fs::path(VCT_SOURCE_DIR) / ".." / "shared" / "assets");
    return roots;
}

}  // namespace

std::optional<fs::path> findAsset(const fs::path& relative) {
    for (const fs::path& root : assetRoots()) {
        const fs::path candidate = root / relative;
        std::error_code ec;
        if (fs::is_regular_file(candidate, ec))
            return fs::absolute(candidate, ec).lexically_normal();
    }
    return std::nullopt;
}

std::string assetSearchPathDescription() {
    const char* env = std::getenv("VCT_ASSET_DIR");
    std::string text = (env && *env) ? concat("$VCT_ASSET_DIR=", env) : "$VCT_ASSET_DIR (unset)";
    const std::vector<fs::path> roots = assetRoots();
    for (std::size_t i = (env && *env) ? 1 : 0; i < roots.size(); ++i)
        text += ", " + roots[i].lexically_normal().string();
    return text;
}

// ------------------------------------------------------------------------------------------------
// --scene values

namespace {

Scene loadSponza(const LoadOptions& options) {
    const std::optional<fs::path> path = findAsset(fs::path("sponza") / "Sponza.gltf");
    if (!path)
        fail("Sponza not found in the asset search path (", assetSearchPathDescription(),
             "); run assets/fetch_sponza.sh or set VCT_ASSET_DIR");
    Scene scene = loadModelFile(*path, options);
    scene.name = "sponza";

    // The file's four cameras (CameraMain, CameraAlternate, CameraBalcony, CameraAlcove) are
    // the presets, CameraMain first.
    std::stable_partition(scene.cameras.begin(), scene.cameras.end(),
                          [](const Camera& c) { return c.name == "CameraMain"; });

    // Sponza is y-up, its long axis along x, open to the sky above the atrium. The sun comes
    // down steeply, slightly along +x and +z, so it lights a strip of the floor and the lower
    // walls through the roof opening while the galleries stay in shadow (indirect light only).
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(glm::dvec3(0.25, -1.0, 0.12));
    sun.irradiance = 10.0;  // W/m²
    scene.lights = {sun};
    // A lit floor of albedo ~0.5 reflects L = 0.5/π · 10 · cosθ ≈ 1.5 W/(m²·sr), which the ACES
    // curve keeps below white at EV 0, while the galleries lit only indirectly (≈ 1/50 of that)
    // stay visible; one stop darker (EV −1) loses them in black.
    scene.exposureEV = 0.0;
    return scene;
}

}  // namespace

Scene loadScene(const std::string& sceneSpec, const LoadOptions& options) {
    if (sceneSpec.empty())
        fail("no scene given; use --scene cornell, --scene sponza or --scene <model file>");
    if (sceneSpec == "cornell") return makeCornellBox();
    if (sceneSpec == "sponza") return loadSponza(options);
    return loadModelFile(sceneSpec, options);
}

}  // namespace vct
