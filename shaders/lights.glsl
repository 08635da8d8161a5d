// Light evaluation in physical units, the GLSL twin of engine/scene/light.hpp (DESIGN 5.3).

#include "math.glsl"
const int LIGHT_DIRECTIONAL = 0;
const int LIGHT_SPOT = 1;

struct LightParams {
    int type;
    vec3 direction;     // unit, direction of travel
    vec3 position;      // scene-local, spot only
    vec3 radiometric;   // directional: E·colour (W/m²); spot: I·colour (W/sr)
    float cosInner;
    float cosOuter;
};

// smoothstep in cos α between the outer and inner cone (see spotFalloff in light.hpp).
float spotFalloff(float cosAngle, float cosInner, float cosOuter) {
    if (cosInner - cosOuter <= 0.0) return cosAngle >= cosOuter ? 1.0 : 0.0;
    float t = clamp((cosAngle - cosOuter) / (cosInner - cosOuter), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

// Irradiance arriving at `p` on a surface perpendicular to the light (no cosθ, no shadow), the
// unit vector towards the light, and the distance to it (directional: infinite, returned as -1).
vec3 incidentIrradiance(LightParams light, vec3 p, out vec3 toLight, out float distanceToLight) {
    if (light.type == LIGHT_DIRECTIONAL) {
        toLight = -light.direction;
        distanceToLight = -1.0;
        return light.radiometric;
    }
    vec3 d = light.position - p;
    float d2 = max(dot(d, d), 1e-30);
    distanceToLight = sqrt(d2);
    toLight = d / distanceToLight;
    float falloff = spotFalloff(dot(-toLight, light.direction), light.cosInner, light.cosOuter);
    return light.radiometric * (falloff / d2);
}
