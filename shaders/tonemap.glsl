// Display transform: exposure, a tone curve, then the sRGB transfer function.
const int TONEMAP_ACES = 0;      // Narkowicz's fit of the ACES filmic curve
const int TONEMAP_REINHARD = 1;  // x / (1 + x)
const int TONEMAP_CLAMP = 2;     // no curve: values above 1 clip

vec3 toneCurve(vec3 x, int curve) {
    if (curve == TONEMAP_ACES) return clamp(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
    if (curve == TONEMAP_REINHARD) return x / (1.0 + x);
    return clamp(x, 0.0, 1.0);
}

vec3 linearToSrgb(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}
