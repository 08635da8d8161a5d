#!/bin/bash
# The GI sweeps of Cornell and of the four Sponza camera presets (vct bench, one sweep file each),
# then one table of them side by side: for every point of the sweeps, the indirect light's mean
# ratio to the path tracer's on each view, how far the views are from 1 together (the mean and
# the largest |log2 ratio|) and what the point costs. Defaults are tuned on this table, not on
# one view: a setting that helps one view and hurts another shows here.
#
#   benchmarks/gi_views.sh                 run the five sweeps (about an hour on llvmpipe), then table
#   benchmarks/gi_views.sh --table-only    table the CSVs already in the results folder
# Environment: VCT (the binary; default build/vct), OUT (results folder; default benchmarks/results).
# Writes OUT/gi_views.md. Sponza comes from the asset search path (docs/cli.md).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
vct=${VCT:-$root/build/vct}
out=${OUT:-$root/benchmarks/results}
views=(cornell sponza sponza_alternate sponza_balcony sponza_alcove)

if [ "${1:-}" != --table-only ]; then
    for view in "${views[@]}"; do
        "$vct" bench "$root/benchmarks/sweeps/$view.json" --out "$out"
    done
fi

for view in "${views[@]}"; do
    [ -f "$out/bench_$view.csv" ] || { echo "gi_views: $out/bench_$view.csv is missing; run without --table-only" >&2; exit 1; }
done

# Engine rows of every CSV, keyed by point label; columns found by their header names.
awk -F, -v views="${views[*]}" '
    BEGIN { nviews = split(views, view, " ") }
    FNR == 1 {
        file++
        for (i = 1; i <= NF; i++) col[$i] = i
        next
    }
    $col["kind"] == "engine" {
        label = $col["label"]
        if (!(label in seen)) { seen[label] = 1; order[++npoints] = label }
        ratio[label, file] = $col["indirect_ratio"]
        if (view[file] == "cornell") cornellRmse[label] = $col["indirect_rmse"]
        if (view[file] == "sponza") {
            staticMs[label] = $col["frame_static_ms"]
            mainSsim[label] = $col["ssim"]
            mainRmse[label] = $col["indirect_rmse"]
        }
    }
    function abs(x) { return x < 0 ? -x : x }
    END {
        printf "| point |"
        for (v = 1; v <= nviews; v++) printf " %s |", view[v]
        printf " mean \\|log2\\| | worst \\|log2\\| | Cornell indirect RMSE | Main SSIM | Main indirect RMSE | Main static ms |\n"
        printf "|---|"
        for (v = 1; v <= nviews + 6; v++) printf "---|"
        printf "\n"
        for (p = 1; p <= npoints; p++) {
            label = order[p]
            sum = 0; worst = 0; n = 0
            printf "| %s |", label
            for (v = 1; v <= nviews; v++) {
                if ((label, v) in ratio) {
                    r = ratio[label, v]
                    printf " %.2f |", r
                    if (r > 0) { e = abs(log(r) / log(2)); sum += e; n++; if (e > worst) worst = e }
                } else printf " |"
            }
            if (n == nviews) printf " %.3f | %.3f |", sum / n, worst
            else printf " (%d of %d views) | |", n, nviews
            printf " %s | %s | %s | %s |\n", cornellRmse[label], mainSsim[label], mainRmse[label], staticMs[label]
        }
    }' $(for view in "${views[@]}"; do echo "$out/bench_$view.csv"; done) > "$out/gi_views.table"

{
    echo "# Indirect light on every view: the GI sweeps side by side"
    echo
    echo "Produced by \`benchmarks/gi_views.sh\` on $(date -u +%Y-%m-%d) at commit $(git -C "$root" describe --always --dirty 2>/dev/null || echo unknown)" \
         "from the CSVs of \`vct bench\` for: ${views[*]} (benchmarks/sweeps/<view>.json; each view's own report is bench_<view>.md)."
    echo "Each cell is the engine's mean indirect luminance over the path tracer's (1 bounce) on that view at that point;"
    echo "1 is exact. A point swept on only some views shows blanks. Times: Sponza CameraMain, llvmpipe, fastest static-geometry frame."
    echo
    cat "$out/gi_views.table"
} > "$out/gi_views.md"
rm "$out/gi_views.table"
echo "gi_views: wrote $out/gi_views.md"
