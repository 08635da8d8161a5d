#version 450
// The raster half of the performance guard's calibration (engine/bench/perf_calibration.hpp):
// layers of small overlapping quads over the whole target, each layer at its own depth, with no
// vertex buffer (the vertex index says where each corner goes).
uniform int uCellsPerSide;

out vec2 vCellUv;

const vec2 kCorners[6] = vec2[](vec2(0, 0), vec2(1, 0), vec2(1, 1), vec2(0, 0), vec2(1, 1), vec2(0, 1));

void main() {
    const int cellsPerLayer = uCellsPerSide * uCellsPerSide;
    const int corner = gl_VertexID % 6;
    const int cell = (gl_VertexID / 6) % cellsPerLayer;
    const int layer = gl_VertexID / (6 * cellsPerLayer);
    // Quads 1.5 cells wide, shifted per layer: neighbours and layers overlap, as real meshes do.
    const vec2 shift = fract(vec2(0.37, 0.61) * float(layer));
    const vec2 cellPosition = vec2(cell % uCellsPerSide, cell / uCellsPerSide) + shift + 1.5 * kCorners[corner];
    const float depth = fract(0.618034 * float(layer) + 0.001 * float(cell % 97));
    gl_Position = vec4(cellPosition / float(uCellsPerSide) * 2.0 - 1.0, depth * 2.0 - 1.0, 1.0);
    vCellUv = kCorners[corner];
}
