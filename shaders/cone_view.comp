#version 450
layout(local_size_x = 8, local_size_y = 8) in;
// Debug view `--view cones`: what a cone sees. Per pixel, one cone leaves the eye along the
// pixel's ray and marches through the radiance pools exactly as the cones that gather indirect
// light do (cone_march.glsl): the same slabs, reads ahead, levels and compositing. It is as wide
// as the cone set's cap (× --cone-aperture), or with --cone-rays as wide as a narrow cone, and
// samples as those do. Its accumulated radiance is what such a cone brings back from that
// direction; where the voxels and the cones' reading of them are right it equals the mean over the
// cone's solid angle of the radiance leaving the surfaces seen there, which the frame's
// `--aov direct` holds pixel by pixel (the light that one bounce reflects). Their ratio, from an
// eye placed on a surface whose indirect light is wrong, says which of the directions it gathers
// from are misread, and where along them.
#include "cone_march.glsl"

layout(rgba32f, binding = IMAGE_VOXEL_VIEW) uniform writeonly image2D uOutput;

uniform vec3 uEyeVoxel;              // camera position in voxel space
uniform vec3 uForward, uRight, uUp;  // camera basis (voxel space = scaled scene-local, same directions)
uniform vec2 uTanHalfFov;            // tan(fovX/2), tan(fovY/2)
uniform float uViewTanHalfAngle;     // the cone's aperture

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(uOutput);
    if (any(greaterThanEqual(pixel, size))) return;
    vec2 ndc = (vec2(pixel) + 0.5) / vec2(size) * 2.0 - 1.0;
    vec3 direction = normalize(uForward + ndc.x * uTanHalfFov.x * uRight + ndc.y * uTanHalfFov.y * uUp);
    // An eye outside the grid starts its cone where the ray enters it.
    vec2 span = rayBox(uEyeVoxel, 1.0 / direction, vec3(0.0), vec3(float(1 << uLevels)));
    vec4 seen = vec4(0.0);
    if (span.y > max(span.x, 0.0)) {
        vec3 origin = uEyeVoxel + direction * max(span.x, 0.0);
        coneAxis = direction;
        coneSpread(direction, uViewTanHalfAngle, coneAlongPlus, coneAlongMinus);
        // The direction stands in for the surface normal: the cone is as far from "its surface"
        // as it has travelled, so its footprint alone sets its level.
        seen = traceCone(origin, direction, direction, uViewTanHalfAngle, uConeOffset);
    }
    imageStore(uOutput, pixel, seen);
}
