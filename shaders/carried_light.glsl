// The last frame's indirect light, carried over camera moves (render/cone_carry.hpp): what
// cone_carry.comp and cone_upsample.comp read of it.

// The last frame's pixels: the point each one's light belongs to (xyz scene-local; w = 1 + the
// frames it has been carried, 0: none), its unit normal, and its indirect irradiance and visibility.
layout(binding = TEXTURE_CARRIED_AT) uniform sampler2D uCarriedAt;
layout(binding = TEXTURE_CARRIED_NORMAL) uniform sampler2D uCarriedNormal;
layout(binding = TEXTURE_CARRIED_IRRADIANCE) uniform sampler2D uCarriedIrradiance;

uniform int uCarry;  // 0: nothing is carried (another scene, a later sample)
