#version 450
// Light-view map: the scene seen from a light. Depth makes it the shadow map; position, normal
// and reflected flux per texel make it the photon source of the GI pipeline (DESIGN §4 pass 7).
#include "material.glsl"
#include "lights.glsl"

in vec3 vPosition;
in vec3 vNormal;
in vec2 vUv;
in vec3 vColor;

uniform LightParams uLight;
uniform float uInverseQuantity;  // 1 / (E or I × the colour's largest component)

layout(location = 0) out vec4 outPosition;  // scene-local, 1
layout(location = 1) out vec4 outNormal;    // facing the light
layout(location = 2) out vec4 outFlux;      // reflected flux ρ·Φ of this texel / the light's largest texel flux

void main() {
    vec4 base = materialBaseColor(vUv, vColor);
    vec3 toLight;
    float distanceToLight;
    vec3 incident = incidentIrradiance(uLight, vPosition, toLight, distanceToLight);
    // Flux through one texel: E·A for a parallel beam (a tilted surface covers more area but
    // receives E·cosθ, so the texel's flux does not depend on θ); I·weight·ω for a spot or a point
    // light's cube face, where the texel's solid angle shrinks as cos³ away from the view's axis.
    // Stored relative to the light's largest texel flux (E or I × colour × footprint,
    // LightViewMap::maxTexelFlux), computed without the light's magnitude so that nothing
    // overflows or underflows float.
    vec3 flux = uLight.radiometric * uInverseQuantity;  // the tint, largest component 1
    if (uLight.type != LIGHT_DIRECTIONAL) {
        float cosAxis = max(dot(-toLight, uLight.direction), 0.0);
        flux *= angularWeight(uLight, -toLight) * cosAxis * cosAxis * cosAxis;
    }
    outPosition = vec4(vPosition, 1.0);
    outNormal = vec4(facingNormal(vNormal, facingGeometricNormal(vPosition, toLight)), 0.0);
    outFlux = vec4(base.rgb * flux, 0.0);
}
