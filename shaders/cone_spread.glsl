// How much of a cone travels along each axis direction (cone_trace.comp). A cone is a bundle of
// directions d around its axis, not one direction: a floor edge-on to the axis of a horizontal
// cone still fills the lower part of its footprint. A surface's opacity along d is its area
// projected along d, the sum over the axes of its area projected along a times |d_a|; averaged
// over the cone's directions, axis a counts E[|d_a|], split into what travels along +a,
// E[max(d_a, 0)], and along −a, E[max(−d_a, 0)]. The spread is modelled as normal: d_a has mean
// c_a·E[cos φ] and variance (1 − c_a²)·E[sin² φ]/2 (φ: angle from the axis c, uniform over the
// cone's cap).

// Standard normal distribution function, through erf (Abramowitz & Stegun 7.1.26, within 1.5e-7).
// Its tails must be accurate: E[max(x, 0)] below is the difference of two nearly equal terms
// there, and a cruder Φ makes it negative, a negative weight on what lies ahead.
float normalCdf(float z) {
    float x = abs(z) * 0.70710678;
    float t = 1.0 / (1.0 + 0.3275911 * x);
    float poly = t * (0.254829592 + t * (-0.284496736 + t * (1.421413741 + t * (-1.453152027 + t * 1.061405429))));
    float erfAbs = 1.0 - poly * exp(-x * x);
    return 0.5 * (1.0 + sign(z) * erfAbs);
}

// E[max(x, 0)] for x normal with mean mu and deviation sigma.
float positivePartMean(float mu, float sigma) {
    if (sigma < 1e-4) return max(mu, 0.0);
    float z = mu / sigma;
    return mu * normalCdf(z) + sigma * 0.39894228 * exp(-0.5 * z * z);
}

// E[max(d_a, 0)] (alongPlus) and E[max(−d_a, 0)] (alongMinus) per axis for the cone of unit axis
// `axis` and half-angle atan(tanHalfAngle). alongPlus − alongMinus = E[d_a].
void coneSpread(vec3 axis, float tanHalfAngle, out vec3 alongPlus, out vec3 alongMinus) {
    // E[sin² φ] over the cap = (1 − cos α)(2 + cos α)/3, with 1 − cos α written without the
    // cancellation that loses it for narrow cones in single precision.
    float secant = sqrt(1.0 + tanHalfAngle * tanHalfAngle);
    float cosHalfAngle = 1.0 / secant;
    float oneMinusCos = tanHalfAngle * tanHalfAngle / (secant * (secant + 1.0));
    float cosMean = 0.5 * (1.0 + cosHalfAngle);
    float sin2Mean = oneMinusCos * (2.0 + cosHalfAngle) / 3.0;
    for (int a = 0; a < 3; ++a) {
        float mu = axis[a] * cosMean;
        float sigma = sqrt(max((1.0 - axis[a] * axis[a]) * sin2Mean * 0.5, 0.0));
        alongPlus[a] = max(positivePartMean(mu, sigma), 0.0);  // float rounding in the far tail
        alongMinus[a] = max(alongPlus[a] - mu, 0.0);
    }
}
