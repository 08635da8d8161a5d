#!/usr/bin/env bash
# Which cones are wrong, and where: for Cornell and the four Sponza presets, the light each cone
# of the default 5-cone set gathers alone (`vct render --only-cone K`) against the path tracer's
# light arriving in that cone's region of the hemisphere (`vct reference --cone-region K`),
# grouped by where the cone points in the world: ring cones more than 30° below the horizon
# (looking down at the floor), within 30° of it (across), above; the cap (the cone along the
# normal) on walls and on ceilings. An image mean can be right while its cones are not. The same
# for 16 narrow cones (`--cone-rays 16 --only-cone K`: those whose axes lie in cone K's region).
#   bash benchmarks/cone_regions.sh          (about 15 minutes on llvmpipe)
# Writes benchmarks/results/cone_regions_<renderer>.md. Sponza comes from the asset search path.
source "$(dirname "$0")/scratch_setup.sh"
views=("cornell|--scene cornell --width 320 --height 240"
       "CameraMain|--scene sponza --camera CameraMain --width 320 --height 180"
       "CameraAlternate|--scene sponza --camera CameraAlternate --width 320 --height 180"
       "CameraBalcony|--scene sponza --camera CameraBalcony --width 320 --height 180"
       "CameraAlcove|--scene sponza --camera CameraAlcove --width 320 --height 180")
settings=("5-cone set|" "16 narrow cones|--cone-rays 16")
for entry in "${views[@]}"; do
  name=${entry%%|*}
  read -r -a options <<< "${entry#*|}"
  echo "cone regions: $name..." >&2
  ./build/vct -q render "${options[@]}" --aov direct --hdr-out "$work/$name-direct.pfm" --out "$work/x.png" \
    --timings "$work/timings.json"
  ./build/vct -q render "${options[@]}" --aov normal --hdr-out "$work/$name-normal.pfm" --out "$work/x.png"
  for cone in 0 1 2 3 4; do
    for s in "${!settings[@]}"; do
      read -r -a extra <<< "${settings[$s]#*|}"
      ./build/vct -q render "${options[@]}" "${extra[@]}" --only-cone "$cone" --aov gi \
        --hdr-out "$work/$name-engine$s-$cone.pfm" --out "$work/x.png"
    done
    ./build/vct -q reference "${options[@]}" --spp 256 --bounces 1 --cones 5 --cone-region "$cone" \
      --out "$work/x.pfm" --indirect-out "$work/$name-reference$cone.pfm"
  done
done
names=()
for entry in "${views[@]}"; do names+=("${entry%%|*}"); done
/usr/bin/python3 - "$work" "$out" "${#settings[@]}" "${settings[@]}" "${names[@]}" <<'PY'
import math, sys
sys.path.insert(0, "benchmarks")
from report import luminance, read_pfm, renderer_of, report_head, write_report
work, out, count = sys.argv[1], sys.argv[2], int(sys.argv[3])
settings, names = [s.split("|")[0] for s in sys.argv[4:4 + count]], sys.argv[4 + count:]

# The 5-cone set (render/cone_set.cpp): the cap and a ring of 4 at sin²θ = 0.6, azimuths j·90°.
ring_sin, ring_cos = math.sqrt(0.6), math.sqrt(0.4)
groups = ["ring, down", "ring, across", "ring, up", "cap on walls", "cap on ceilings", "cap on floors"]
rows = []
for name in names:
    width, height, normal = read_pfm(f"{work}/{name}-normal.pfm")
    reference = [read_pfm(f"{work}/{name}-reference{k}.pfm")[2] for k in range(5)]
    for index, setting in enumerate(settings):
        engine = [read_pfm(f"{work}/{name}-engine{index}-{k}.pfm")[2] for k in range(5)]
        sums = {g: [0.0, 0.0] for g in groups}
        for i in range(width * height):
            nx, ny, nz = normal[i]
            length = math.sqrt(nx * nx + ny * ny + nz * nz)
            if length < 0.5:
                continue  # sky
            nx, ny, nz = nx / length, ny / length, nz / length
            # The engine's tangent frame (shaders/math.glsl orthonormalBasis); only its y matters here.
            s = 1.0 if nz >= 0.0 else -1.0
            a = -1.0 / (s + nz)
            b = nx * ny * a
            tangent_y, bitangent_y = s * b, s + ny * ny * a
            for k in range(5):
                if k == 0:
                    group = "cap on walls" if abs(ny) <= 0.5 else ("cap on floors" if ny > 0.0 else "cap on ceilings")
                else:
                    cosine, sine = [(1, 0), (0, 1), (-1, 0), (0, -1)][k - 1]
                    axis_y = ring_sin * (cosine * tangent_y + sine * bitangent_y) + ring_cos * ny
                    group = "ring, down" if axis_y < -0.5 else ("ring, up" if axis_y > 0.5 else "ring, across")
                sums[group][0] += luminance(engine[k][i])
                sums[group][1] += luminance(reference[k][i])
        total = sum(r for _, r in sums.values())
        cells = []
        for g in groups:
            e, r = sums[g]
            cells.append(f"{e / r:.2f} ({100.0 * r / total:.0f} %)" if r > 0.01 * total else "–")
        engine_total = sum(e for e, _ in sums.values())
        rows.append(f"| {name} | {setting} | {engine_total / total:.2f} | " + " | ".join(cells) + " |")

renderer, tag = renderer_of(f"{work}/timings.json")
lines = report_head("Each cone's light against the path tracer's in its region", renderer, "cone_regions.sh",
                    "256³ voxels, the 5-cone set and 16 narrow cones; `vct render --only-cone K --aov gi` against "
                    "`vct reference --bounces 1 --spp 256 --cone-region K`, summed over the image by where cone K "
                    "points in the world: ring cones more than 30° below the horizon (down), within 30° of it (across) "
                    "or above (up); the cap (the cone along the normal) on walls, ceilings and floors. Each cell: "
                    "engine / reference (the group's share of the reference's indirect light).",
                    ["view", "cones", "all"] + groups) + rows
write_report(f"{out}/cone_regions_{tag}.md", lines)
PY
