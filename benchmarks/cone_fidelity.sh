#!/usr/bin/env bash
# What one cone brings back, against what it should: for a few probes (an eye a voxel or two off a
# surface and a direction), the cone of `vct render --view cones` along that direction (the cone
# set's cap, and a narrow cone) against the mean over the same cone's solid angle of the radiance
# that `--aov direct` shows there (the light one bounce reflects). Unlike the image ratios of the
# other scripts this isolates the march of one cone through the voxels from the cone set's weights
# and the pixels' surfaces ([docs/benchmark.md](../docs/benchmark.md#what-one-cone-sees)).
#   bash benchmarks/cone_fidelity.sh          (a few minutes on llvmpipe)
# Writes benchmarks/results/cone_fidelity_<renderer>.md.
source "$(dirname "$0")/scratch_setup.sh"

# A 4 × 3 m sheet turned 45° about the vertical, lit from the front by a sun; specks at z = ±8 make
# the grid 16 m wide (voxels of 12.5 cm at 128³).
cat >"$work/sheet45.obj" <<'OBJ'
v -1.41421 0 1.41421
v 1.41421 0 -1.41421
v 1.41421 3 -1.41421
v -1.41421 3 1.41421
v 0 0 8
v 0.05 0 8
v 0 0.05 8
v 0 0 -8
v 0.05 0 -8
v 0 0.05 -8
f 1 2 3
f 1 3 4
f 5 6 7
f 8 9 10
OBJ
sheet="--scene $work/sheet45.obj --sun-dir 0.3,-0.5,-1 --voxel-levels 7"
# name | scene options | eye | direction
probes=("sunlit floor of Sponza's courtyard, from 5.6 m above|--scene sponza|0,8,0|0,-1,0"
        "Cornell ceiling, down at the lit floor and boxes|--scene cornell|0,1.97,0|0,-1,0"
        "Cornell left wall, across the box|--scene cornell|-0.97,1,0|1,0,0"
        "sheet turned 45°, from 6 m in front|$sheet|0,1.5,6|0,0,-1"
        "Sponza gallery wall (CameraAlcove), to the courtyard|--scene sponza|-10,6,7.3|0,-0.15,-1"
        "Sponza gallery vault (CameraBalcony), down to the courtyard|--scene sponza|8,12.5,4.5|0,-0.6,-1")
# name | tan of the half-angle | options: the 5-cone set's cap has sin² of its half-angle 1/5
# (render/cone_set.cpp), so tan ½; a narrow cone tan 0.03 (render/cone_trace.hpp, kNarrowConeTan).
cones=("cone set's cap|0.5|" "narrow cone|0.03|--cone-rays 1")
for i in "${!probes[@]}"; do
  IFS='|' read -r name scene eye direction <<<"${probes[$i]}"
  target=$(/usr/bin/python3 -c "e=[$eye]; d=[$direction]; print(','.join(str(a + b) for a, b in zip(e, d)))")
  up=0,1,0
  [ "$direction" = 0,-1,0 ] && up=1,0,0
  for j in "${!cones[@]}"; do
    IFS='|' read -r _ tan options <<<"${cones[$j]}"
    echo "cone fidelity: $name, ${cones[$j]%%|*}..." >&2
    # shellcheck disable=SC2086
    ./build/vct -q render $scene $options --eye "$eye" --target "$target" --up "$up" --fov 2 --width 9 --height 9 \
      --view cones --hdr-out "$work/c$i-$j.pfm" --out "$work/c$i-$j.png" --timings "$work/t.json" 2>/dev/null
    fov=$(/usr/bin/python3 -c "import math; print(min(2.2 * math.degrees(math.atan($tan)), 170))")
    # shellcheck disable=SC2086
    ./build/vct -q render $scene $options --eye "$eye" --target "$target" --up "$up" --fov "$fov" --width 256 --height 256 \
      --aov direct --hdr-out "$work/d$i-$j.pfm" --out "$work/d$i-$j.png" 2>/dev/null
    echo "$tan $fov" >"$work/a$i-$j.txt"
  done
done
/usr/bin/python3 - "$work" "$out" "${#probes[@]}" "${probes[@]}" "${cones[@]}" <<'PY'
import math, sys
sys.path.insert(0, "benchmarks")
from report import luminance, read_pfm, renderer_of, report_head, write_report
work, out, count = sys.argv[1], sys.argv[2], int(sys.argv[3])
probes, cones = sys.argv[4:4 + count], sys.argv[4 + count:]

def cone_value(i, j):  # the centre pixel of the cone view
    width, height, pixels = read_pfm(f"{work}/c{i}-{j}.pfm")
    return luminance(pixels[(height // 2) * width + width // 2])

def expected(i, j):  # the solid-angle mean of the direct AOV inside the cone
    tan, fov = map(float, open(f"{work}/a{i}-{j}.txt").read().split())
    width, height, pixels = read_pfm(f"{work}/d{i}-{j}.pfm")
    half = math.tan(math.radians(fov / 2))
    total = weight = 0.0
    for y in range(height):
        for x in range(width):
            u, v = ((x + 0.5) / width * 2 - 1) * half, ((y + 0.5) / height * 2 - 1) * half
            if u * u + v * v > tan * tan:
                continue
            w = (1 + u * u + v * v) ** -1.5  # solid angle of the pixel
            total += w * luminance(pixels[y * width + x])
            weight += w
    return total / weight

renderer, tag = renderer_of(f"{work}/t.json")
lines = report_head("What one cone sees", renderer, "cone_fidelity.sh",
                    "One cone (`vct render --view cones`, the centre pixel of a 2° view) from the eye along the "
                    "direction, against the mean over the same cone of the radiance `--aov direct` shows (what one "
                    "bounce reflects): the ratio, then both values (luminance, W/(m²·sr)). 256³ unless the scene says "
                    "otherwise; every other setting at its default.",
                    ["probe (eye, direction)"] + [c.split("|")[0] for c in cones])
for i, probe in enumerate(probes):
    name, _, eye, direction = probe.split("|")
    cells = []
    for j in range(len(cones)):
        seen, should = cone_value(i, j), expected(i, j)
        cells.append(f"{seen / should:.2f}× ({seen:.4f} / {should:.4f})" if should > 0 else f"— ({seen:.4f} / 0)")
    lines.append(f"| {name} ({eye}; {direction}) | " + " | ".join(cells) + " |")
write_report(f"{out}/cone_fidelity_{tag}.md", lines)
PY
