#pragma once
// Light-view map (DESIGN §4 pass 7): the scene rendered from one light. Position, normal and
// reflected flux per texel are the photons that the GI pipeline injects into the voxel octree;
// a depth map is the shadow map of the direct pass. The two want different resolutions: a shadow
// edge is as sharp as the shadow map's texels, far finer than a voxel, while a few photons per
// voxel face suffice. With a finer shadow map the scene is drawn a second time, depth only, at
// its resolution; at the same resolution the photons' depth is the shadow map. A sun or a spot has one map; a point light has six,
// the faces of a cube around it (render/cube_faces.hpp), and every pass takes them one by one.
#include <vector>

#include "gl/objects.hpp"
#include "render/gpu_scene.hpp"
#include "render/view.hpp"

namespace vct {

// The programs every light-view map is drawn with: the photons (scene.vert + light_view.frag)
// and the finer shadow map's depth-only draw: opaque materials with no fragment shader (the
// rasterizer's depth alone), masked ones with shadow_depth.frag, which only runs the alpha test.
struct LightViewPrograms {
    gl::Program photons, shadowOpaque, shadowMasked;
};
LightViewPrograms lightViewPrograms();

class LightViewMap {
public:
    LightViewMap(int photonResolution, int shadowResolution);
    // `face`: which cube face of a point light this map shows (0 for the other lights).
    // `programs`: lightViewPrograms(), shared by every map.
    void render(const LightViewPrograms& programs, const GpuScene& gpuScene, const Scene& scene,
                const Light& light, int face = 0);

    // DEPTH32F, compare mode GL_GEQUAL, shadowResolution() texels per side.
    GLuint shadowMap() const { return shadowDepth_.id() ? shadowDepth_.id() : depth_.id(); }
    GLuint position() const { return position_.id(); }  // RGBA32F scene-local, w=0 empty
    GLuint normal() const { return normal_.id(); }      // RGBA16F facing the light
    // RGBA32F reflected flux ρ·Φ of each texel *relative to* the light's largest texel flux
    // maxTexelFlux() (so in [0, ρ] whatever the light's units and the scene's size: the watts, up
    // to 1e20 W/m² × (1e18 m)², would overflow float; half floats lost even 1e-4 W/sr).
    GLuint flux() const { return flux_.id(); }
    // Watts of a texel of relative flux 1: quantity (E or I) × largest colour component × footprint.
    static double maxTexelFlux(const Light& light, const LightViewTransform& transform);
    const LightViewTransform& transform() const { return transform_; }
    int resolution() const { return resolution_; }  // of the photons
    int shadowResolution() const { return shadowResolution_; }
    // The shadow map's texel edge (LightViewTransform::texelWorldSize at its resolution).
    float shadowTexelWorldSize() const { return transform_.texelWorldSize * float(resolution_) / float(shadowResolution_); }
    int face() const { return face_; }
    std::size_t bytes() const;

private:
    int resolution_, shadowResolution_;
    int face_ = 0;
    gl::Texture depth_, position_, normal_, flux_;
    gl::Texture shadowDepth_;  // only when finer than the photons
    gl::Framebuffer framebuffer_, shadowFramebuffer_;
    LightViewTransform transform_;
};

// How many maps a light needs: six for a point light (a cube), one for the others.
int lightViewCount(const Light& light);

// Texels per side of each of the light's shadow maps for `--shadow-res` `requested`: a point
// light's cube faces get half. A face spans 90°, so at half the scene's size from the light its
// texels are about as wide as those of a sun's map over the whole scene; six full-size faces
// would cost six maps' memory and fill for edges no finer than the sun's.
int shadowMapSide(const Light& light, int requested);

// Every light's maps, in the order of the scene's lights.
using LightViewSets = std::vector<std::vector<LightViewMap>>;

}  // namespace vct
