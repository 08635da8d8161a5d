#version 450
// The raster half of the calibration: some arithmetic per fragment, like a material lookup and
// shading, written to a float colour target.
uniform int uFragmentIterations;

in vec2 vCellUv;
out vec4 colour;

void main() {
    vec3 c = vec3(vCellUv, 0.5);
    for (int i = 0; i < uFragmentIterations; ++i) c = fract(c * 1.7 + sin(c.zxy * 3.1));
    colour = vec4(c, 1.0);
}
