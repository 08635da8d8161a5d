#version 450
layout(local_size_x = 64) in;
// radiance_leaves, after the border lists: brick samples outside the border are set to no light
// over the geometry's density along their direction, (0, 0, 0, τ±a) (brick_layout.hpp, "Slabs"),
// so that a cone reads one pool per direction and finds the opacity of unlit geometry there too.
// The border nodes are written by radiance_leaves and radiance_mip, so they are left alone. Every
// other node's bricks once (after the volume is allocated or the geometry's bricks change); after
// that, with CLEAR_BORDER, only those of the previous filtering's border nodes that are not on the
// border again: the only ones that can still hold light. (A light that moves a little keeps most
// of its border; clearing those bricks only for radiance_leaves to write them again cost a fifth
// of the filtering.)
#include "voxel_common.glsl"
#include "octree.glsl"
#include "bricks_common.glsl"
#include "directional_pool.glsl"
#include "radiance_common.glsl"

layout(binding = TEXTURE_OPACITY_PLUS) uniform sampler3D uOpacityPlus;
layout(binding = TEXTURE_OPACITY_MINUS) uniform sampler3D uOpacityMinus;
layout(rgba32f, binding = IMAGE_DIRECTIONAL_RADIANCE) uniform writeonly image3D uDirectional;

uniform uint uNodeCount;

void main() {
    uint node = linearInvocation();
    if (node >= uNodeCount) return;
#if defined(CLEAR_BORDER)
    if (borderFlag[node] != BORDER_BEFORE) return;
#else
    if ((borderFlag[node] & BORDER_NOW) != 0u) return;
#endif
    ivec3 origin = brickOrigin(node);
    for (int s = 0; s < 27; ++s) {
        ivec3 local = blockCoord3(s);
        vec3 plus = texelFetch(uOpacityPlus, origin + local, 0).xyz, minus = texelFetch(uOpacityMinus, origin + local, 0).xyz;
        for (int a = 0; a < 3; ++a) {
            imageStore(uDirectional, directionalBrickOrigin(node, 2 * a) + local, vec4(0.0, 0.0, 0.0, plus[a]));
            imageStore(uDirectional, directionalBrickOrigin(node, 2 * a + 1) + local, vec4(0.0, 0.0, 0.0, minus[a]));
        }
    }
}
