#include "bench/bench_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

#include <unistd.h>

#include "core/error.hpp"

namespace vct::bench {
namespace {

std::string num(double v, const char* format = "%.6g") {
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    if (std::isnan(v)) return "nan";
    char text[48];
    std::snprintf(text, sizeof text, format, v);
    return text;
}

// Lower is better.
double errorOf(const BenchRow& r, Quality q) {
    switch (q) {
        case Quality::Rmse: return r.error.rmse;
        case Quality::IndirectRmse: return r.error.indirectRmse;
        case Quality::Ssim: return 1.0 - r.error.ssim;
    }
    return r.error.rmse;
}

std::vector<const BenchRow*> curveOf(const std::vector<BenchRow>& rows) {
    std::vector<const BenchRow*> curve;
    for (const auto& r : rows)
        if (r.kind == "pathtracer") curve.push_back(&r);
    std::sort(curve.begin(), curve.end(), [](const BenchRow* a, const BenchRow* b) { return a->spp < b->spp; });
    return curve;
}

const BenchRow* defaultRow(const std::vector<BenchRow>& rows) {
    for (const auto& r : rows)
        if (r.kind == "engine" && r.isDefault) return &r;
    return nullptr;
}

// Engine pass costs summed by the stage of the frame each pass belongs to (the pass table's).
double stageMs(const BenchRow& r, Stage stage) {
    double ms = 0.0;
    for (const auto& p : r.passes)
        for (const PassDeclaration& pass : framePasses())
            if (pass.stage == stage && p.name == pass.name) ms += p.ms();
    return ms;
}

// The default point's per-region indirect ratios, for the CSV: the extremes over the significant
// cells and every cell's ratio, row-major from the top left, ';'-separated, empty where undefined.
std::string regionCsvColumns(const BenchRow& r) {
    if (!r.indirectRegions) return ",,";
    const metrics::RegionRatios& regions = *r.indirectRegions;
    auto optional = [](const std::optional<double>& v) { return v ? num(*v) : std::string(); };
    std::string cells;
    for (const auto& cell : regions.cells) {
        if (&cell != &regions.cells.front()) cells += ';';
        cells += optional(cell.ratio);
    }
    return optional(regions.minRatioSignificant) + "," + optional(regions.maxRatioSignificant) + "," + cells;
}

void writeRegionTable(std::ostringstream& md, const metrics::RegionRatios& regions) {
    md << "## Indirect light per region (default point)\n\n";
    md << "The image cut into " << regions.columns << "×" << regions.rows
       << " cells (rows top to bottom as the image is seen); per cell the mean luminance of the engine's indirect "
          "part over the reference's, and in parentheses the cell's share of the reference's indirect light. Cells "
          "whose reference mean is at most "
       << num(100.0 * metrics::kSignificantCellFraction, "%g")
       << " % of the image's are in italics and left out of the extremes; - where undefined (no reference "
          "indirect light). `vct compare --regions "
       << regions.columns << "x" << regions.rows << "` prints the same table for any pair of images.\n\n|   |";
    for (int column = 0; column < regions.columns; ++column) md << " column " << column << " |";
    md << "\n|---|";
    for (int column = 0; column < regions.columns; ++column) md << "---|";
    md << "\n";
    for (int row = 0; row < regions.rows; ++row) {
        md << "| row " << row << " |";
        for (int column = 0; column < regions.columns; ++column) {
            const metrics::RegionCell& cell = regions.cell(column, row);
            if (!cell.ratio) {
                md << " - |";
                continue;
            }
            const std::string ratio = num(*cell.ratio, "%.3f") + "×";
            md << " " << (cell.significant ? ratio : "*" + ratio + "*") << " (" << num(100.0 * cell.share, "%.1f")
               << " %) |";
        }
        md << "\n";
    }
    md << "\n";
    if (regions.minRatioSignificant)
        md << "Over the significant cells the ratio runs from " << num(*regions.minRatioSignificant, "%.3f") << " to "
           << num(*regions.maxRatioSignificant, "%.3f") << " (whole image "
           << num(regions.meanA / regions.meanB, "%.3f") << ").\n\n";
    else
        md << "No cell holds enough reference indirect light to count.\n\n";
}

std::string quoteShell(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

std::string quoteGnuplot(const std::string& s) {
    std::string q = "\"";
    for (char c : s) q += (c == '"' || c == '\\') ? std::string("\\") + c : std::string(1, c);
    return q + "\"";
}

bool findInPath(const std::string& program) {
    const char* path = std::getenv("PATH");
    if (!path) return false;
    std::stringstream dirs(path);
    std::string dir;
    while (std::getline(dirs, dir, ':')) {
        if (dir.empty()) continue;
        std::error_code ec;
        const auto candidate = std::filesystem::path(dir) / program;
        if (std::filesystem::is_regular_file(candidate, ec) && access(candidate.c_str(), X_OK) == 0) return true;
    }
    return false;
}

// Tick marks at 1, 2, 5 × 10^k covering [lo, hi], labelled with %g (log axes spanning less than a
// decade otherwise get one labelled tick).
std::string ticks125(std::pair<double, double> range) {
    if (!(range.second > 0.0) || !(range.first <= range.second)) return "1";
    std::string list;
    const int k0 = int(std::floor(std::log10(range.first))) - 1, k1 = int(std::ceil(std::log10(range.second))) + 1;
    for (int k = k0; k <= k1; ++k)
        for (double m : {1.0, 2.0, 5.0}) {
            const double v = m * std::pow(10.0, k);
            char text[48];
            std::snprintf(text, sizeof text, "\"%g\" %g", v, v);
            if (!list.empty()) list += ", ";
            list += text;
        }
    return list;
}

std::string shortLabel(const BenchRow& r) {
    if (r.isDefault) return "default";
    static const std::map<std::string, std::string> names = {
        {"voxel_levels", "L"},  {"cones", "cones "},      {"cone_aperture", "aperture "}, {"cone_step", "step "},
        {"cone_offset", "offset "}, {"cone_lift", "lift "}, {"light_view_res", "light view "}, {"pcf_radius", "pcf "}};
    if (r.parameter == "bricks") return r.value == "true" ? "bricks" : "no bricks";
    if (r.parameter == "gi") return r.value == "true" ? "GI on" : "GI off";
    auto it = names.find(r.parameter);
    return (it == names.end() ? r.parameter + "=" : it->second) + r.value;
}

}  // namespace

const char* qualityName(Quality q) {
    switch (q) {
        case Quality::Rmse: return "full-image RMSE";
        case Quality::IndirectRmse: return "indirect RMSE";
        case Quality::Ssim: return "SSIM";
    }
    return "?";
}

double qualityValue(const BenchRow& r, Quality q) { return q == Quality::Ssim ? r.error.ssim : errorOf(r, q); }

std::vector<bool> paretoFront(const std::vector<BenchRow>& rows, Quality quality) {
    std::vector<bool> front(rows.size(), false);
    for (std::size_t i = 0; i < rows.size(); ++i) {
        if (rows[i].kind != "engine") continue;
        bool dominated = false;
        for (std::size_t j = 0; j < rows.size() && !dominated; ++j) {
            if (j == i || rows[j].kind != "engine") continue;
            const double ti = rows[i].frameMs, tj = rows[j].frameMs;
            const double ei = errorOf(rows[i], quality), ej = errorOf(rows[j], quality);
            dominated = tj <= ti && ej <= ei && (tj < ti || ej < ei);
        }
        front[i] = !dominated;
    }
    return front;
}

EqualErrorSpeedup bestEqualErrorSpeedup(const std::vector<BenchRow>& rows, Quality quality) {
    EqualErrorSpeedup best;
    for (const BenchRow& r : rows) {
        if (r.kind != "engine" || !(r.frameStaticMs > 0.0)) continue;
        const EqualErrorTime t = pathTracerTimeAt(rows, qualityValue(r, quality), quality);
        if (!t.valid) continue;
        const double speedup = t.ms / r.frameStaticMs;
        if (!best.row || speedup > best.speedup) best = {&r, t, speedup};
    }
    return best;
}

void markPareto(std::vector<BenchRow>& rows) {
    const std::vector<bool> front = paretoFront(rows, Quality::Rmse);
    for (std::size_t i = 0; i < rows.size(); ++i) rows[i].pareto = front[i];
}

EqualErrorTime pathTracerTimeAt(const std::vector<BenchRow>& rows, double value, Quality quality) {
    EqualErrorTime result;
    const std::vector<const BenchRow*> curve = curveOf(rows);
    const double target = quality == Quality::Ssim ? 1.0 - value : value;
    if (curve.empty() || !(target > 0.0)) return result;
    const bool canExtrapolate = quality != Quality::Ssim;
    const BenchRow& first = *curve.front();
    const double eFirst = errorOf(first, quality);
    if (target >= eFirst) {
        if (target > eFirst && !canExtrapolate) {
            result.how = concat("worse than the path tracer at ", first.spp, " spp");
            return result;
        }
        result.valid = true;
        result.ms = first.frameMs * (eFirst / target) * (eFirst / target);
        result.extrapolated = target > eFirst;
        result.how = result.extrapolated ? concat("below ", first.spp, " spp (extrapolated, time ∝ 1/RMSE²)")
                                         : concat("at ", first.spp, " spp");
        return result;
    }
    for (std::size_t i = 0; i + 1 < curve.size(); ++i) {
        const double e0 = errorOf(*curve[i], quality), e1 = errorOf(*curve[i + 1], quality);
        if (e0 >= target && target >= e1 && e0 > e1) {
            const double f = (std::log(e0) - std::log(target)) / (std::log(e0) - std::log(e1));
            result.valid = true;
            result.ms = std::exp(std::log(curve[i]->frameMs) + f * (std::log(curve[i + 1]->frameMs) - std::log(curve[i]->frameMs)));
            result.how = concat("between ", curve[i]->spp, " and ", curve[i + 1]->spp, " spp");
            return result;
        }
    }
    // Below the whole curve: the noise floor of the reference makes this a rough estimate.
    const BenchRow& last = *curve.back();
    if (!canExtrapolate) {
        result.how = concat("better than the path tracer at ", last.spp, " spp");
        return result;
    }
    const double e = errorOf(last, quality);
    result.valid = true;
    result.ms = last.frameMs * (e / target) * (e / target);
    result.extrapolated = true;
    result.how = concat("beyond ", last.spp, " spp (extrapolated, time ∝ 1/RMSE²)");
    return result;
}

std::string describeSettings(const PointSettings& s) {
    std::string text;
    for (const auto& p : parameterNames()) text += (text.empty() ? "" : ", ") + p + "=" + parameterValue(s, p);
    return text;
}

void writeCsv(const std::filesystem::path& path, const std::vector<BenchRow>& rows) {
    const std::vector<bool> frontIndirect = paretoFront(rows, Quality::IndirectRmse);
    std::vector<std::string> passNames;
    for (const auto& r : rows)
        for (const auto& p : r.passes)
            if (std::find(passNames.begin(), passNames.end(), p.name) == passNames.end()) passNames.push_back(p.name);

    std::ofstream out(path);
    out << "kind,label,parameter,value,is_default,spp";
    for (const auto& p : parameterNames()) out << "," << p;
    out << ",frame_ms,frame_static_ms,frame_ms_all_repeats,update_ms,update_passes,setup_ms,memory_mib,cone_samples"
           ",rmse,relmse,psnr,ssim,direct_rmse,indirect_rmse,indirect_relmse,indirect_ratio,pareto,pareto_indirect"
           ",incremental_identical,indirect_region_ratio_min,indirect_region_ratio_max,indirect_region_ratios";
    for (const auto& p : passNames) out << ",ms_" << p;
    out << "\n";
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const BenchRow& r = rows[i];
        const bool engine = r.kind == "engine";
        out << r.kind << "," << r.label << "," << r.parameter << "," << r.value << "," << (r.isDefault ? 1 : 0) << ","
            << (engine ? "" : std::to_string(r.spp));
        for (const auto& p : parameterNames()) out << "," << (engine ? parameterValue(r.settings, p) : "");
        std::string all;
        for (double ms : r.frameSamplesMs) {
            if (!all.empty()) all += ';';
            all += num(ms, "%.2f");
        }
        out << "," << num(r.frameMs, "%.3f") << "," << num(r.frameStaticMs, "%.3f") << "," << all << ","
            << (engine ? num(r.updateMs, "%.3f") : "") << "," << r.updatePasses << ","
            << (engine ? "" : num(r.setupMs, "%.3f")) << ","
            << (engine ? num(double(r.memoryBytes) / (1024.0 * 1024.0), "%.2f") : "") << ","
            << (engine ? std::to_string(r.coneSamples) : "");
        out << "," << num(r.error.rmse) << "," << num(r.error.relMse) << "," << num(r.error.psnr) << ","
            << num(r.error.ssim) << "," << num(r.error.directRmse) << "," << num(r.error.indirectRmse) << ","
            << num(r.error.indirectRelMse) << "," << num(r.error.indirectRatio) << "," << (r.pareto ? 1 : 0) << ","
            << (frontIndirect[i] ? 1 : 0) << "," << (engine ? (r.incrementalIdentical ? "1" : "0") : "") << ","
            << regionCsvColumns(r);
        for (const auto& name : passNames) {
            out << ",";
            for (const auto& p : r.passes)
                if (p.name == name) out << num(p.ms(), "%.3f");
        }
        out << "\n";
    }
    if (!out) fail("cannot write '", path.string(), "' (disk full?)");
}

void writeMarkdown(const std::filesystem::path& path, const std::vector<BenchRow>& rows, const BenchSummary& s,
                   const std::string& chartFile) {
    std::ostringstream md;
    const BenchRow* def = defaultRow(rows);
    md << "# Run time against error: " << s.scene << " (sweep `" << s.name << "`)\n\n";
    md << "Produced by `" << s.command << "` on " << s.date
       << (s.commit.empty() ? std::string() : " at commit " + s.commit)
       << (s.shaderDir.empty() ? std::string() : ", shaders from " + s.shaderDir + " (VCT_SHADER_DIR)")
       << ". Engine: " << s.renderer << " (" << s.backend
       << "); CPU: " << s.cpu << ". Image " << s.width << "×" << s.height << ", camera `" << s.camera
       << "`, display for PSNR/SSIM: " << num(s.exposureEV) << " EV, " << s.tonemap << ".";
    if (!s.loadBefore.empty())
        md << " Load average (1, 5, 15 min) at the start " << s.loadBefore << ", at the end " << s.loadAfter
           << ": the cores were shared with other work, which is why every time is the fastest of several runs.";
    md << "\n\n";
    if (!s.note.empty()) md << "Note: " << s.note << "\n\n";
    md << "Ground truth: `vct reference` with " << s.referenceBounces << " indirect bounce"
       << (s.referenceBounces == 1 ? "" : "s") << ", " << s.referenceSpp << " spp, seed " << s.referenceSeed << " ("
       << num(s.referenceSeconds, "%.1f") << " s, direct-only " << num(s.referenceDirectSeconds, "%.1f") << " s"
       << (s.referenceFromCache ? ", read from benchmarks/cache" : "") << "; key " << s.referenceKey
       << "). Its own noise, √(mean variance) = " << num(s.referenceNoiseRmse, "%.3g")
       << " RMSE, is the floor under every error below. Indirect part: engine final − engine direct AOV, reference "
          "full − reference direct-only (bounces 0). The path-tracer curve uses seed "
       << s.curveSeed << " (independent of the reference's samples), " << s.referenceBounces << " bounce"
       << (s.referenceBounces == 1 ? "" : "s") << ", " << s.pathTracerThreads << " threads; its time excludes the BVH build. "
          "A `bounces` point is measured against a reference with its own number of bounces (same spp and seed, "
          "cached alike). A `samples` point's image averages that many pixel samples (the first full, the others "
          "re-running the camera's passes), and its times are those of all its samples together.\n\n";
    md << "Engine timing: one-at-a-time sweep around the default (" << s.defaultSettings
       << "). `frame ms` is the fastest of " << s.repeats
       << " warm full frames (every pass, octree included) as max(GPU span, Σ pass CPU ms), because llvmpipe runs "
          "compute passes on the CPU at submission; `static ms` is the fastest of as many frames in which lights "
          "and camera move (nudged by 10⁻⁴) over static geometry: every pass but the octree's; `update ms` is the "
          "frame after switching from the default to the point (only the passes that depend on the change). "
          "`memory` is the GPU pools the renderer holds at the point (the voxel fragment list keeps capacity an "
          "earlier point grew it to). Both renderers run on the same CPU cores here, so the speedups below are "
          "CPU-against-CPU numbers; on a GPU the engine's side changes by orders of magnitude.\n\n";
    if (!chartFile.empty()) md << "![error against time](" << chartFile << ")\n\n";

    md << "## Summary\n\n";
    if (def) {
        md << "- Default point: full image RMSE " << num(def->error.rmse, "%.4g") << ", relMSE "
           << num(def->error.relMse, "%.4g") << ", PSNR " << num(def->error.psnr, "%.2f") << " dB, SSIM "
           << num(def->error.ssim, "%.4f") << "; indirect part RMSE " << num(def->error.indirectRmse, "%.4g")
           << ", relMSE " << num(def->error.indirectRelMse, "%.4g") << ", mean " << num(def->error.indirectRatio, "%.3f")
           << "× the reference's; direct part RMSE " << num(def->error.directRmse, "%.4g") << ". Frame "
           << num(def->frameMs, "%.1f") << " ms (static geometry " << num(def->frameStaticMs, "%.1f") << " ms).\n";
        for (Quality q : {Quality::Rmse, Quality::IndirectRmse, Quality::Ssim}) {
            const double v = qualityValue(*def, q);
            const EqualErrorTime t = pathTracerTimeAt(rows, v, q);
            md << "- Equal " << qualityName(q) << " (" << num(v, "%.4g") << "): ";
            if (!t.valid) {
                md << "not on the path tracer's curve (" << t.how << ").\n";
                continue;
            }
            md << "the path tracer needs " << num(t.ms, "%.1f") << " ms (" << t.how << "): "
               << num(t.ms / def->frameMs, "%.3g") << "× the engine's full frame, "
               << num(t.ms / def->frameStaticMs, "%.3g") << "× its static-geometry frame.\n";
        }
    }
    if (const EqualErrorSpeedup best = bestEqualErrorSpeedup(rows, Quality::Rmse); best.row)
        md << "- Best equal full-image RMSE over the points: " << best.row->label << " (RMSE "
           << num(best.row->error.rmse, "%.4g") << "): the path tracer needs " << num(best.time.ms, "%.1f") << " ms ("
           << best.time.how << "), " << num(best.speedup, "%.3g") << "× the point's static-geometry frame ("
           << num(best.row->frameStaticMs, "%.1f") << " ms).\n";
    for (Quality q : {Quality::Rmse, Quality::IndirectRmse, Quality::Ssim}) {
        const std::vector<bool> front = paretoFront(rows, q);
        std::vector<const BenchRow*> list;
        for (std::size_t i = 0; i < rows.size(); ++i)
            if (front[i]) list.push_back(&rows[i]);
        std::sort(list.begin(), list.end(), [](auto* a, auto* b) { return a->frameMs < b->frameMs; });
        md << "- Pareto front (" << qualityName(q) << " against frame ms):";
        for (std::size_t i = 0; i < list.size(); ++i)
            md << (i ? "," : "") << " " << list[i]->label << " (" << num(list[i]->frameMs, "%.0f") << " ms, "
               << num(qualityValue(*list[i], q), "%.4g") << ")";
        md << "\n";
    }
    bool allIdentical = true;
    for (const auto& r : rows)
        if (r.kind == "engine") allIdentical = allIdentical && r.incrementalIdentical;
    md << "- Incrementally updated images identical to full frames at every point: " << (allIdentical ? "yes" : "**no**")
       << ".\n\n";

    if (def && def->indirectRegions) writeRegionTable(md, *def->indirectRegions);

    md << "## Engine points\n\n";
    md << "| point | frame ms | static ms | update ms | memory MiB | RMSE | relMSE | PSNR dB | SSIM | direct RMSE | "
          "indirect RMSE | indirect relMSE | indirect ratio | Pareto |\n";
    md << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& r : rows) {
        if (r.kind != "engine") continue;
        md << "| " << (r.isDefault ? "**default**" : r.label) << " | " << num(r.frameMs, "%.1f") << " | "
           << num(r.frameStaticMs, "%.1f") << " | " << num(r.updateMs, "%.1f") << " | "
           << num(double(r.memoryBytes) / (1024.0 * 1024.0), "%.1f") << " | " << num(r.error.rmse, "%.4g") << " | "
           << num(r.error.relMse, "%.4g") << " | " << num(r.error.psnr, "%.2f") << " | " << num(r.error.ssim, "%.4f")
           << " | " << num(r.error.directRmse, "%.4g") << " | " << num(r.error.indirectRmse, "%.4g") << " | "
           << num(r.error.indirectRelMse, "%.4g") << " | " << num(r.error.indirectRatio, "%.3f") << " | "
           << (r.pareto ? "●" : "") << " |\n";
    }
    md << "\n## Path tracer\n\n";
    md << "| spp | time ms | RMSE | relMSE | PSNR dB | SSIM | direct RMSE | indirect RMSE | indirect relMSE |\n";
    md << "|---|---|---|---|---|---|---|---|---|\n";
    for (const BenchRow* r : curveOf(rows))
        md << "| " << r->spp << " | " << num(r->frameMs, "%.1f") << " | " << num(r->error.rmse, "%.4g") << " | "
           << num(r->error.relMse, "%.4g") << " | " << num(r->error.psnr, "%.2f") << " | "
           << num(r->error.ssim, "%.4f") << " | " << num(r->error.directRmse, "%.4g") << " | "
           << num(r->error.indirectRmse, "%.4g") << " | " << num(r->error.indirectRelMse, "%.4g") << " |\n";
    md << "\n## Engine pass costs by stage (ms, fastest full frame; a pass costs max(GPU ms, CPU ms))\n\n| point |";
    for (std::size_t s = 0; s < std::size_t(Stage::Count); ++s) md << " " << stageName(Stage(s)) << " |";
    md << "\n|---|";
    for (std::size_t s = 0; s < std::size_t(Stage::Count); ++s) md << "---|";
    md << "\n";
    for (const auto& r : rows) {
        if (r.kind != "engine") continue;
        md << "| " << r.label << " |";
        for (std::size_t s = 0; s < std::size_t(Stage::Count); ++s) md << " " << num(stageMs(r, Stage(s)), "%.1f") << " |";
        md << "\n";
    }
    std::ofstream out(path);
    out << md.str();
    if (!out) fail("cannot write '", path.string(), "' (disk full?)");
}

std::string writeChart(const std::filesystem::path& script, const std::filesystem::path& png,
                       const std::vector<BenchRow>& rows, const BenchSummary& s) {
    const std::vector<bool> frontFull = paretoFront(rows, Quality::Rmse),
                            frontIndirect = paretoFront(rows, Quality::IndirectRmse);
    std::ostringstream gp;
    gp << "# Drawn by `vct bench` (" << s.command << "); run `gnuplot " << script.filename().string()
       << "` in this folder to draw it again.\n";
    gp << "set terminal pngcairo size 2100,700 enhanced font 'DejaVu Sans,10'\n";
    // Relative to the script's folder, where gnuplot runs, so the script works wherever it lies.
    gp << "set output " << quoteGnuplot(png.filename().string()) << "\n";
    auto block = [&](const char* name, auto select) {
        std::vector<const BenchRow*> list;
        for (std::size_t i = 0; i < rows.size(); ++i)
            if (select(i)) list.push_back(&rows[i]);
        std::sort(list.begin(), list.end(), [](auto* a, auto* b) { return a->frameMs < b->frameMs; });
        gp << "$" << name << " << EOD\n";
        for (const BenchRow* r : list)
            gp << num(r->frameMs, "%.4g") << " " << num(r->error.rmse, "%.6g") << " "
               << num(r->error.indirectRmse, "%.6g") << " "
               << quoteGnuplot(r->kind == "engine" ? shortLabel(*r) : std::to_string(r->spp)) << "\n";
        gp << "EOD\n";
    };
    block("engine", [&](std::size_t i) { return rows[i].kind == "engine"; });
    block("pathtracer", [&](std::size_t i) { return rows[i].kind == "pathtracer"; });
    block("pareto", [&](std::size_t i) { return bool(frontFull[i]); });
    block("paretoIndirect", [&](std::size_t i) { return bool(frontIndirect[i]); });
    block("default", [&](std::size_t i) { return rows[i].kind == "engine" && rows[i].isDefault; });
    std::pair<double, double> fullRange{1e300, 0.0}, indirectRange{1e300, 0.0}, timeRange{1e300, 0.0};
    auto extend = [](std::pair<double, double>& r, double v) {
        if (v > 0.0 && std::isfinite(v)) r = {std::min(r.first, v), std::max(r.second, v)};
    };
    std::pair<double, double> engineTime{1e300, 0.0}, engineError{1e300, 0.0};
    for (const auto& r : rows) {
        extend(fullRange, r.error.rmse);
        extend(indirectRange, r.error.indirectRmse);
        extend(timeRange, r.frameMs);
        if (r.kind != "engine") continue;
        extend(engineTime, r.frameMs);
        extend(engineError, r.error.rmse);
    }
    extend(fullRange, s.referenceNoiseRmse);
    extend(indirectRange, s.referenceNoiseRmse);
    gp << "set xtics (" << ticks125(timeRange) << ")\n";
    gp << "noise = " << num(s.referenceNoiseRmse > 0 ? s.referenceNoiseRmse : 1e-30, "%.6g") << "\n";
    gp << "set multiplot layout 1,3 title "
       << quoteGnuplot(concat(s.scene, " ", s.width, "x", s.height, ": error against time, vct settings and the path ",
                              "tracer (", s.referenceBounces, " bounce, reference ", s.referenceSpp, " spp), ",
                              s.renderer, ", ", s.date))
       << " font ',12'\n";
    gp << "set logscale xy\nset grid xtics ytics mxtics mytics lc rgb '#e0e0e0'\n";
    gp << "set xlabel 'time (ms, log): vct full warm frame / path-tracer render, same CPU'\n";
    gp << "set key bottom left box opaque font ',9'\nset offsets graph 0.08, graph 0.25, graph 0.1, graph 0.1\n";
    gp << "set autoscale fix\n";
    for (int panel = 0; panel < 2; ++panel) {
        const int column = panel == 0 ? 2 : 3;
        gp << "set ytics (" << ticks125(column == 2 ? fullRange : indirectRange) << ")\n";
        gp << "set ylabel '" << (panel == 0 ? "RMSE of the full image" : "RMSE of the indirect part")
           << " vs reference (linear, log)'\n";
        gp << "set title '" << (panel == 0 ? "full image" : "indirect part alone (final − direct)") << "'\n";
        gp << "plot $pathtracer using 1:" << column
           << " with linespoints pt 5 ps 0.8 lw 1.5 lc rgb '#d62728' title 'path tracer (spp)', \\\n"
           << "     $pathtracer using 1:" << column
           << ":(sprintf('%s spp', strcol(4))) with labels offset char 0,-0.9 font ',8' tc rgb '#d62728' notitle, \\\n"
           << "     " << (panel == 0 ? "$pareto" : "$paretoIndirect") << " using 1:" << column
           << " with linespoints pt 4 ps 1.9 lw 2 dt 2 lc rgb '#1f77b4' title 'Pareto front (vct)', \\\n"
           << "     $engine using 1:" << column << " with points pt 7 ps 1.0 lc rgb '#1f77b4' title 'vct settings', \\\n"
           << "     $engine using 1:" << column << ":4 with labels left offset char 0.6,0.35 font ',8' noenhanced notitle, \\\n"
           << "     $default using 1:" << column << " with points pt 6 ps 2.4 lw 2 lc rgb 'black' title 'vct default', \\\n"
           << "     noise with lines dt 3 lc rgb '#808080' title 'reference noise (est.)'\n";
    }
    // Third panel: the engine's points alone, so that their labels can be read.
    if (engineTime.second > 0.0) {
        // At least 5 % of the error: one point alone (a sweep of the default only) still gets a
        // y range gnuplot can draw, whatever digits the range is written with.
        const double span = std::max({engineError.second - engineError.first, 0.05 * engineError.second, 1e-9});
        gp << "set offsets 0, 0, 0, 0\nunset logscale y\nset ytics auto\nset format y '%g'\n";
        gp << "set xtics (" << ticks125(engineTime) << ")\n";
        gp << "set xrange [" << num(engineTime.first / 1.3) << ":" << num(engineTime.second * 1.8) << "]\n";
        gp << "set yrange [" << num(std::max(0.0, engineError.first - 0.08 * span)) << ":"
           << num(engineError.second + 0.08 * span) << "]\n";
        gp << "set key top left box opaque font ',9'\n";
        gp << "set ylabel 'RMSE of the full image vs reference (linear)'\n";
        gp << "set title 'vct points only (zoom; full image)'\n";
        gp << "plot $pareto using 1:2 with linespoints pt 4 ps 1.9 lw 2 dt 2 lc rgb '#1f77b4' title 'Pareto front (vct)', \\\n"
           << "     $engine using 1:2 with points pt 7 ps 1.0 lc rgb '#1f77b4' notitle, \\\n"
           << "     $engine using 1:2:4 with labels left offset char 0.6,0.35 font ',8' noenhanced notitle, \\\n"
           << "     $default using 1:2 with points pt 6 ps 2.4 lw 2 lc rgb 'black' title 'vct default', \\\n"
           << "     $pathtracer using 1:2 with linespoints pt 5 ps 0.8 lw 1.5 lc rgb '#d62728' notitle, \\\n"
           << "     $pathtracer using 1:2:(sprintf('%s spp', strcol(4))) with labels offset char 0,-0.9 font ',8' tc rgb '#d62728' notitle\n";
    }
    gp << "unset multiplot\n";
    {
        std::ofstream out(script);
        out << gp.str();
        if (!out) fail("cannot write '", script.string(), "' (disk full?)");
    }
    if (!findInPath("gnuplot"))
        return concat("gnuplot is not installed, so no chart was drawn; the data and the script are in ",
                      script.string(), ". Install it (Debian: apt-get install gnuplot-nox) and run: gnuplot ",
                      script.string());
    std::filesystem::remove(png);
    const std::filesystem::path folder = script.parent_path().empty() ? "." : script.parent_path();
    const std::string command =
        "cd " + quoteShell(folder.string()) + " && gnuplot " + quoteShell(script.filename().string()) + " 2>&1";
    std::string output;
    if (FILE* pipe = popen(command.c_str(), "r")) {
        char buffer[1024];
        while (std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) output.append(buffer, n);
        const int status = pclose(pipe);
        if (status == 0 && std::filesystem::exists(png)) return "";
        return concat("gnuplot failed on ", script.string(), " (exit status ", status, "): ", output);
    }
    return concat("cannot run gnuplot: ", command);
}

}  // namespace vct::bench
