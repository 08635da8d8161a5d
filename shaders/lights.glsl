// Light evaluation in physical units, the GLSL twin of engine/scene/light.hpp (DESIGN 5.3).

#include "math.glsl"
const int LIGHT_DIRECTIONAL = 0;
const int LIGHT_SPOT = 1;
const int LIGHT_POINT = 2;

// A point light is drawn as six views, the faces of a cube around it; every pass that uses a
// light-view map sees one face at a time. A face's share of the light is exactly the directions
// whose largest component lies along its axis (cubeFace), so the six faces add up to the whole
// light once, with no seam counted twice or left out.
struct LightParams {
    int type;
    vec3 direction;     // unit, direction of travel; a point light's view: its cube face's axis
    vec3 position;      // scene-local, spot and point
    vec3 radiometric;   // directional: E·colour (W/m²); spot and point: I·colour (W/sr)
    float cosInner;
    float cosOuter;
    int face;           // point light: the cube face this view shows (cubeFace's numbering)
};

// smoothstep in cos α between the outer and inner cone (see spotFalloff in light.hpp).
float spotFalloff(float cosAngle, float cosInner, float cosOuter) {
    if (cosInner - cosOuter <= 0.0) return cosAngle >= cosOuter ? 1.0 : 0.0;
    float t = clamp((cosAngle - cosOuter) / (cosInner - cosOuter), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

// Cube face of a direction: 0/1 = +x/−x, 2/3 = +y/−y, 4/5 = +z/−z (the twin of cubeFaceOf in
// engine/render/cube_faces.hpp). Ties go to the earlier axis, so every direction has one face.
int cubeFace(vec3 v) {
    vec3 a = abs(v);
    if (a.x >= a.y && a.x >= a.z) return v.x >= 0.0 ? 0 : 1;
    if (a.y >= a.z) return v.y >= 0.0 ? 2 : 3;
    return v.z >= 0.0 ? 4 : 5;
}

// The share of the light's quantity that leaves it towards `fromLight` (unit, light → point):
// the spot's falloff, 1 or 0 for a point light's face, 1 for a sun.
float angularWeight(LightParams light, vec3 fromLight) {
    if (light.type == LIGHT_SPOT) return spotFalloff(dot(fromLight, light.direction), light.cosInner, light.cosOuter);
    if (light.type == LIGHT_POINT) return cubeFace(fromLight) == light.face ? 1.0 : 0.0;
    return 1.0;
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
    return light.radiometric * (angularWeight(light, -toLight) / d2);
}
