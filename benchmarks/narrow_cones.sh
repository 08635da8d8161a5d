#!/usr/bin/env bash
# The cone set against narrow cones (`--cone-rays`) on Cornell, the four Sponza presets and the
# four Sponza views no test uses: the indirect part (final − direct AOV) against the path
# tracer's (`vct reference --bounces 1 --spp 512`, its --indirect-out), as its mean ratio, the
# ratios of its 3×3 cells (reference above 5 % of the image's mean), its RMSE, and the image's
# SSIM (`vct compare`). Each setting below is one column.
#   bash benchmarks/narrow_cones.sh          (about 15 minutes on llvmpipe, most of it references)
# Writes benchmarks/results/narrow_cones_<renderer>.md.
source "$(dirname "$0")/scratch_setup.sh"
views=("Cornell|--scene cornell --width 320 --height 240|0.5"
       "CameraMain|--scene sponza --camera CameraMain --width 320 --height 180|-1"
       "CameraAlternate|--scene sponza --camera CameraAlternate --width 320 --height 180|-1"
       "CameraBalcony|--scene sponza --camera CameraBalcony --width 320 --height 180|-1"
       "CameraAlcove|--scene sponza --camera CameraAlcove --width 320 --height 180|-1"
       "view 1|--scene sponza --eye 0,4.5,0 --target 20,6,3 --width 320 --height 180|-1"
       "view 2|--scene sponza --eye -5,4.5,-2 --target -25,8,2 --width 320 --height 180|-1"
       "view 3|--scene sponza --eye 5,12,-4 --target -20,12,-7 --width 320 --height 180|-1"
       "view 4|--scene sponza --eye 0,4.5,3 --target -20,7,-3 --width 320 --height 180|-1")
settings=("5-cone set (default)|"
          "16 narrow|--cone-rays 16"
          "16 narrow, --cone-step 1|--cone-rays 16 --cone-step 1")
for i in "${!views[@]}"; do
  IFS='|' read -r name args exposure <<<"${views[$i]}"
  echo "narrow cones: $name, reference..." >&2
  # shellcheck disable=SC2086
  ./build/vct -q reference $args --spp 512 --bounces 1 --out "$work/ref$i.pfm" --indirect-out "$work/ref$i-indirect.pfm"
  for j in "${!settings[@]}"; do
    IFS='|' read -r _ options <<<"${settings[$j]}"
    echo "narrow cones: $name, ${settings[$j]%%|*}..." >&2
    # shellcheck disable=SC2086
    ./build/vct -q render $args $options --hdr-out "$work/e$i-$j.pfm" --out "$work/e$i-$j.png" --timings "$work/t.json"
    # shellcheck disable=SC2086
    ./build/vct -q render $args $options --aov direct --hdr-out "$work/d$i-$j.pfm" --out "$work/d$i-$j.png"
    ./build/vct -q compare "$work/e$i-$j.pfm" "$work/ref$i.pfm" --exposure "$exposure" --json "$work/c$i-$j.json" >/dev/null
  done
done
/usr/bin/python3 - "$work" "$out" "${#views[@]}" "${#settings[@]}" "${views[@]}" "${settings[@]}" <<'PY'
import json, math, sys
sys.path.insert(0, "benchmarks")
from report import luminance, read_pfm, renderer_of, report_head, write_report
work, out, view_count, setting_count = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
views = sys.argv[5:5 + view_count]
settings = sys.argv[5 + view_count:5 + view_count + setting_count]

def metrics(engine, direct, reference):
    width, height, e = read_pfm(engine)
    _, _, d = read_pfm(direct)
    _, _, r = read_pfm(reference)
    indirect = [tuple(a - b for a, b in zip(pe, pd)) for pe, pd in zip(e, d)]
    rmse = math.sqrt(sum((a - b) ** 2 for pi, pr in zip(indirect, r) for a, b in zip(pi, pr)) / (3 * len(r)))
    le, lr = [luminance(p) for p in indirect], [luminance(p) for p in r]
    mean = sum(lr) / len(lr)
    cells = []
    for cy in range(3):
        for cx in range(3):
            idx = [y * width + x for y in range(cy * height // 3, (cy + 1) * height // 3)
                   for x in range(cx * width // 3, (cx + 1) * width // 3)]
            ref = sum(lr[k] for k in idx) / len(idx)
            if ref > 0.05 * mean:
                cells.append(sum(le[k] for k in idx) / len(idx) / ref)
    return sum(le) / sum(lr), min(cells), max(cells), rmse

renderer, tag = renderer_of(f"{work}/t.json")
lines = report_head("Narrow cones against the cone set", renderer, "narrow_cones.sh",
                    "Indirect part (final − direct AOV) against `vct reference --bounces 1 --spp 512` (its indirect "
                    "part): mean ratio [3×3 cells whose reference exceeds 5 % of the image's mean], indirect RMSE, "
                    "image SSIM (`vct compare`). 256³, every other setting at its default.",
                    ["view"] + [s.split("|")[0] for s in settings])
for i, view in enumerate(views):
    name = view.split("|")[0]
    row = []
    for j in range(len(settings)):
        ratio, low, high, rmse = metrics(f"{work}/e{i}-{j}.pfm", f"{work}/d{i}-{j}.pfm", f"{work}/ref{i}-indirect.pfm")
        ssim = json.load(open(f"{work}/c{i}-{j}.json"))["ssim"]
        row.append(f"{ratio:.3f} [{low:.2f}–{high:.2f}] {rmse:.4f}, {ssim:.3f}")
    lines.append(f"| {name} | " + " | ".join(row) + " |")
write_report(f"{out}/narrow_cones_{tag}.md", lines)
PY
