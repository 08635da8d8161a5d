#!/usr/bin/env bash
# Where the indirect light comes from, surface by surface: for each Sponza preset, the engine's
# indirect light (`--aov gi`), with the default cones (four narrow ones per traced pixel) and with
# 16 narrow cones, and the path tracer's (`--indirect-out`, one bounce) with all materials, then
# with one material group's reflection taken out (`--dark-material`, the same in all three). The
# difference, on every pixel but the material's own (whose shading the option darkens too; found
# from `--aov albedo`), is the light off those surfaces; its ratio engine / reference says which
# surfaces' light the engine gets wrong, and "the rest" is the light off everything else. Light
# that both kinds of cones get wrong alike is not the four cones' noise or coarse sampling.
#   bash benchmarks/light_sources.sh [X,Y,Z]   (about twenty-five minutes on llvmpipe; needs Sponza)
# With X,Y,Z the scene is lit by a sun travelling that way (10 W/m²) instead of Sponza's own
# (benchmarks/sun_directions.sh shows the engine darker under every other sun).
# Writes benchmarks/results/light_sources_<renderer>.md, or with a sun
# light_sources_<renderer>_sun_<X>_<Y>_<Z>.md.
source "$(dirname "$0")/scratch_setup.sh"
spp=256
scene=(--scene sponza)
suffix=""
if [ $# -gt 0 ]; then
  scene+=(--sun-dir "$1" --sun-irradiance 10)
  suffix="_sun_${1//,/_}"
fi
views=(CameraMain CameraAlternate CameraBalcony CameraAlcove)
materials=(Floor 'Fabric*' 'Column*' Arches Bricks)
narrow=(--cone-rays 16 --cone-step 1)
size=(--width 320 --height 180)
for view in "${views[@]}"; do
  for index in -1 "${!materials[@]}"; do
    dark=()
    [ "$index" -ge 0 ] && dark=(--dark-material "${materials[$index]}")
    echo "light sources: $view, ${dark[*]:-all materials}..." >&2
    ./build/vct -q reference "${scene[@]}" --camera "$view" "${size[@]}" "${dark[@]}" --spp $spp --bounces 1 \
      --out "$work/r.pfm" --indirect-out "$work/$view$index-reference.pfm"
    ./build/vct -q render "${scene[@]}" --camera "$view" "${size[@]}" "${dark[@]}" --aov gi \
      --hdr-out "$work/$view$index-engine.pfm" --out "$work/e.png" --timings "$work/timings.json"
    ./build/vct -q render "${scene[@]}" --camera "$view" "${size[@]}" "${dark[@]}" "${narrow[@]}" --aov gi \
      --hdr-out "$work/$view$index-narrow.pfm" --out "$work/e.png"
    ./build/vct -q render "${scene[@]}" --camera "$view" "${size[@]}" "${dark[@]}" --aov albedo \
      --hdr-out "$work/$view$index-albedo.pfm" --out "$work/e.png"
  done
done
/usr/bin/python3 - "$work" "$out" "$spp" "$suffix" "${1-}" "${views[@]}" -- "${materials[@]}" <<'PY'
import functools
import sys
sys.path.insert(0, "benchmarks")
from report import luminance, read_pfm, renderer_of, report_head, write_report
work, out, spp, suffix, sun = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4], sys.argv[5]
split = sys.argv.index("--")
views, materials = sys.argv[6:split], sys.argv[split + 1:]

@functools.lru_cache(maxsize=None)  # each image is read once, though every material's rows use it
def luminances(path):  # per pixel, rows top first
    width, height, pixels = read_pfm(path)
    return width, height, tuple(luminance(pixels[(height - 1 - y) * width + x]) for y in range(height) for x in range(width))

def cells(path, keep=None):  # summed luminance of the image and of its 3×3 cells (row 0 at the top)
    width, height, values = luminances(path)
    total, grid = 0.0, [0.0] * 9
    for i, value in enumerate(values):
        if keep is None or keep[i]:
            total += value
            grid[(i // width) * 3 // height * 3 + (i % width) * 3 // width] += value
    return total, grid

def not_own(view, index):  # pixels that do not show the darkened material itself
    _, _, before = luminances(f"{work}/{view}-1-albedo.pfm")
    _, _, after = luminances(f"{work}/{view}{index}-albedo.pfm")
    return [not (b > 0 and a <= 0) for b, a in zip(before, after)]

def ratios(engine, reference, significant):
    return " ".join(f"{e / r:.2f}" if keep and r > 0 else "–" for e, r, keep in zip(engine, reference, significant))

renderer, tag = renderer_of(f"{work}/timings.json")
lines = report_head("Where the indirect light comes from, surface by surface", renderer, "light_sources.sh",
                    f"Sponza's presets at 320×180, 256³, "
                    + (f"lit by a sun travelling towards ({sun}), 10 W/m² (`--sun-dir`); " if sun else "under Sponza's own sun; ")
                    + "the engine's indirect light (`vct render --aov gi`) with "
                    f"the default cones (four narrow ones per traced pixel) and with 16 narrow cones (`--cone-rays 16 "
                    f"--cone-step 1`), and the path "
                    f"tracer's (`vct reference --bounces 1 --spp {spp} --indirect-out`), with all materials and "
                    "with the named ones dark (`--dark-material`, albedo 0 in all three). The light off a material "
                    "is the difference, over the pixels that do not show the material itself (the option darkens "
                    "those too). Columns: the share of the reference's indirect light there that comes off the "
                    "material; engine / reference of that light over the image and per 3×3 cell (row 0 at the "
                    "top, cells where it is at most 5 % of its mean over the image: –), for each kind of cones; "
                    "engine / reference of the light off every other surface (default, 16 narrow cones).",
                    ["view", "material", "share of the reference's", "default / reference", "per cell",
                     "16 narrow cones / reference", "per cell", "the rest: default, 16 narrow"])
for view in views:
    reference_all, reference_all_cells = cells(f"{work}/{view}-1-reference.pfm")
    significant = [r > 0.05 * reference_all / 9 for r in reference_all_cells]
    row = f"| {view} | (all) | 100 % |"
    for engine in ("engine", "narrow"):
        engine_all, engine_all_cells = cells(f"{work}/{view}-1-{engine}.pfm")
        row += f" {engine_all / reference_all:.2f} | {ratios(engine_all_cells, reference_all_cells, significant)} |"
    lines.append(row + " |")
    for index, material in enumerate(materials):
        keep = not_own(view, index)
        reference_all, reference_all_cells = cells(f"{work}/{view}-1-reference.pfm", keep)
        reference_rest, reference_rest_cells = cells(f"{work}/{view}{index}-reference.pfm", keep)
        reference_off = [a - b for a, b in zip(reference_all_cells, reference_rest_cells)]
        reference_share = 1.0 - reference_rest / reference_all
        significant = [r > 0.05 * max(reference_all - reference_rest, 1e-30) / 9 for r in reference_off]
        row, rest = f"| {view} | `{material}` | {100 * reference_share:.0f} % |", []
        for engine in ("engine", "narrow"):
            engine_all, engine_all_cells = cells(f"{work}/{view}-1-{engine}.pfm", keep)
            engine_rest, engine_rest_cells = cells(f"{work}/{view}{index}-{engine}.pfm", keep)
            engine_off = [a - b for a, b in zip(engine_all_cells, engine_rest_cells)]
            engine_ratio = (engine_all - engine_rest) / max(reference_all - reference_rest, 1e-30)
            row += f" {engine_ratio:.2f} | {ratios(engine_off, reference_off, significant)} |"
            rest.append(f"{engine_rest / reference_rest:.2f}")
        lines.append(row + f" {', '.join(rest)} |")
write_report(f"{out}/light_sources_{tag}{suffix}.md", lines)
PY
