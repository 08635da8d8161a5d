// The one-bounce indirect light against the path tracer (docs/frame.md, "Global illumination"):
// its mean and its 3×3 regions on the Cornell box and on a Sponza view, and no light in a closed
// room beside a sunlit one. The engine's indirect part is final − direct AOV, the reference's is
// its bounces-1 image minus its direct part, as `vct bench` measures them.
//
// The bounds are what the engine reaches today with a margin for llvmpipe's and the reference's
// noise (each test prints its numbers); docs/benchmark.md gives the full measurement on every view.
#include <algorithm>
#include <cmath>
#include <vector>
#include <cstdio>
#include <fstream>

#include <glm/glm.hpp>

#include "bench/reference_cache.hpp"
#include "core/image.hpp"
#include "core/math_constants.hpp"
#include "metrics/image_metrics.hpp"
#include "metrics/region_ratio.hpp"
#include "scene/scene_loader.hpp"
#include "stress_util.hpp"
#include "test_models.hpp"
#include "test_util.hpp"

using namespace vct;

namespace {

// Measured (docs/benchmark.md) and the bounds asserted, with room for noise.
constexpr double kLeakMean = 0.005, kLeakLargestPixel = 0.02;  // of the lit floor's radiance
constexpr double kSheetLargestPixel = 0.05;  // the pixels within a voxel of the sheet (frame.md, Known limits)
// The rooms turned 45° to the grid, room B's end wall lit from outside by a low sun: measured 0.39 %
// on average and 67 % at the worst pixel, a corner's (0.69 % and 84 % before the exit shares were
// signed on a slanted surface's dark side); benchmarks/turned_rooms.sh's other alignment of the
// grid 0.71 %. The mean is the guard; the worst pixel only has to stay below the lit floor.
constexpr double kTurnedRoomLeakMean = 0.005, kTurnedRoomLeakLargestPixel = 0.9;
constexpr double kUnderSheetMean = 0.015, kUnderSheetLargestPixel = 0.02;  // of π·Le
// The default (4 narrow cones) on Cornell: issue 12's bounds (the cone set's cells reached 0.46..1.37).
constexpr double kCornellMean[2] = {0.9, 1.1}, kCornellCells[2] = {0.75, 1.33};
// The cone set (`--cone-rays 0`), which errs more: its measured 0.96x [0.46..1.37] with room.
constexpr double kConeSetCornellMean[2] = {0.85, 1.1}, kConeSetCornellCells[2] = {0.4, 1.4};
constexpr double kSponzaMean[2] = {0.85, 1.1}, kSponzaCells[2] = {0.75, 1.4};
// Sponza under suns other than its own (benchmarks/sun_directions.sh): the indirect light comes out
// darker under every one (CameraMain 128x72: 0.885 [cells 0.73..1.16] under the glTF loader's
// default sun, 0.788 [0.60..1.12] under a low sun from the east). Not issue 12's bounds: a guard
// that tuning under the own sun does not make the others worse.
constexpr double kOtherSunMean[2] = {0.7, 1.1}, kOtherSunCells[2] = {0.45, 1.4};
constexpr double kFurnaceMeanTolerance = 0.05, kFurnaceLowTolerance = 0.1;  // of 1.5
constexpr double kFurnaceBouncesTolerance = 0.05;  // of 1.75 and 1.875 (the acceptance bound)
// The sun's light inside the closed furnace, along its seams (frame.md, Known limits), in units of
// the walls' emitted radiance, per 96² view: measured at most 0.0004 on average, 1 % of the
// pixels above 0.01, 0.32 at one pixel (five views on llvmpipe; an H200 0.28 at the 24² view).
constexpr double kSeamLeakMean = 0.002, kSeamLeakPixelShare = 0.02, kSeamLeakLargest = 0.45;
// Narrow cones (`--cone-rays`): issue 12's bounds on the mean and on the cells, Sponza's too: its
// far arcade under the sunlit gallery, which the leaf bricks' blur darkened, holds them since
// narrow cones thinner than a voxel read the voxels themselves (cone_march.glsl, sampleVoxels).
constexpr double kNarrowMean[2] = {0.9, 1.1}, kNarrowCells[2] = {0.75, 1.33};
constexpr double kNarrowWallRatio[2] = {0.85, 1.15};
// A gallery lit by a sunlit floor it sees at grazing angles (docs/benchmark.md, "Reads across the
// axis within the footprint"): at 128x96, 1.05x, the roof's and back wall's cells 0.92..1.21x;
// 0.93x when reads across the axis out of empty nodes reached a whole spacing past the footprint.
constexpr double kGalleryMean[2] = {0.95, 1.12}, kGalleryCells[2] = {0.85, 1.3};
constexpr double kNarrowSecondBounce[2] = {0.8, 1.25};  // measured 1.03
// The floor beside a low sunlit fin that the camera sees from its dark side: measured 0.07x the
// path tracer's when the near field's ray took a surface met from its hidden side as black, 0.49x
// with that side's light from the voxels, 0.74x since grazing cones start lower (a metre away only
// they see the fin, which is lower than the cones' start offset).
constexpr double kFinFloorAtLeast = 0.55;
// Bounces 2 and 3 in a room lit through an opening (issue 13's 0.85..1.15 for a whole image):
// measured 0.94 with one narrow cone per voxel side (the default), 1.00 with two, 0.64 with the
// cone set.
constexpr double kFurtherBounces[2] = {0.85, 1.15};
constexpr double kNarrowConeCountTolerance = 0.05;
// Sixteen accumulated samples with narrow cones after the first, against sixteen of the cone set:
// the narrow cones' error is the smaller by far (measured: docs/benchmark.md).
constexpr double kAccumulatedNarrowErrorShare = 0.75;
constexpr double kSlabLikeSheetTolerance = 0.1;
// The Cornell box turned about the vertical against itself unturned (the path tracer's images agree
// within 0.1 %): the octree's axes do not turn with it, so the voxels and the six directions of the
// radiance pools meet its walls differently (measured: docs/benchmark.md, "A turned scene").
constexpr double kTurnedMean[2] = {0.9, 1.1}, kTurnedCells[2] = {0.7, 1.4};

ImageF render(const std::filesystem::path& dir, const std::string& name, const std::string& options) {
    const auto out = dir / name;
    const test::CommandResult r =
        test::runVct("render -q " + options + " --out " + out.string() + ".png --hdr-out " + out.string() + ".pfm");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    return readHdrImage(out.string() + ".pfm");
}

// Engine and reference indirect parts of one view.
struct IndirectPair {
    ImageF engine, reference;
};

// `engineOptions`: the engine's own settings, which the reference does not take.
IndirectPair indirectParts(const std::filesystem::path& dir, const std::string& view, int spp,
                           const std::string& engineOptions = "") {
    const ImageF final = render(dir, "final", view + engineOptions);
    const ImageF direct = render(dir, "direct", view + engineOptions + " --aov direct");
    const auto full = dir / "reference.pfm", referenceDirect = dir / "reference_direct.pfm";
    const test::CommandResult r = test::runVct("reference -q " + view + " --bounces 1 --spp " + std::to_string(spp) +
                                               " -o " + full.string() + " --direct-out " + referenceDirect.string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
    return {bench::subtractImages(final, direct), bench::subtractImages(readHdrImage(full), readHdrImage(referenceDirect))};
}

// Checks the image-wide ratio and every significant cell of a 3×3 grid against the bounds.
// `against`: what the reference image is, for the printed line.
void expectIndirectWithin(const IndirectPair& parts, const char* what, double meanLow, double meanHigh,
                          double cellLow, double cellHigh, const char* against = "the path tracer's") {
    const metrics::RegionRatios regions = metrics::regionRatios(parts.engine, parts.reference, 3, 3);
    const double ratio = regions.meanA / regions.meanB;
    std::printf("[ accuracy ] %s: indirect %.3f× %s; significant cells %.2f..%.2f×\n", what, ratio, against,
                regions.minRatioSignificant.value_or(0.0), regions.maxRatioSignificant.value_or(0.0));
    EXPECT_GE(ratio, meanLow) << what;
    EXPECT_LE(ratio, meanHigh) << what;
    for (const metrics::RegionCell& cell : regions.cells) {
        if (!cell.significant || !cell.ratio) continue;
        EXPECT_GE(*cell.ratio, cellLow) << what << ", cell " << cell.column << "," << cell.row;
        EXPECT_LE(*cell.ratio, cellHigh) << what << ", cell " << cell.column << "," << cell.row;
    }
}

// `p` turned by `radians` about the vertical through the origin.
glm::dvec3 aboutVertical(glm::dvec3 p, double radians) {
    return {std::cos(radians) * p.x + std::sin(radians) * p.z, p.y, -std::sin(radians) * p.x + std::cos(radians) * p.z};
}

std::string vectorOption(const char* name, glm::dvec3 v) {
    char text[128];
    std::snprintf(text, sizeof text, " %s %.6f,%.6f,%.6f", name, v.x, v.y, v.z);
    return text;
}

// Two rooms side by side under one roof: room A (x in [0, 1]) open to the sky through a hole in
// its ceiling, room B (beyond the wall, x in [1 + w, 2 + w]) closed; the wall between them is
// `wallVoxels` voxels of a 256³ grid thick (0: a single sheet, lying on the cell face x = 128).
// All surfaces single-sided planes of albedo 0.8. Turned by `turn` radians about the vertical
// through the origin (the wall's thickness in voxels is then that of the unturned rooms' grid).
std::filesystem::path writeTwoRooms(const std::filesystem::path& dir, double wallVoxels, double turn = 0.0) {
    const double w = wallVoxels * 2.0 / (256.0 - wallVoxels);  // the grid spans the scene's 2 + w
    const double W = 2.0 + w, a = 1.0 + w;
    std::ofstream(dir / "rooms.mtl") << "newmtl white\nKd 0.8 0.8 0.8\n";
    std::ofstream obj(dir / "rooms.obj");
    obj << "mtllib rooms.mtl\nusemtl white\n";
    int vertices = 0;
    auto quad = [&](std::initializer_list<glm::dvec3> corners) {
        for (const glm::dvec3& corner : corners) {
            const glm::dvec3 c = aboutVertical(corner, turn);
            obj << "v " << c.x << " " << c.y << " " << c.z << "\n";
        }
        obj << "f " << vertices + 1 << " " << vertices + 2 << " " << vertices + 3 << " " << vertices + 4 << "\n";
        vertices += 4;
    };
    quad({{0, 0, 0}, {W, 0, 0}, {W, 0, 1}, {0, 0, 1}});  // floor
    quad({{0, 0, 0}, {0, 0, 1}, {0, 1, 1}, {0, 1, 0}});  // outer walls
    quad({{W, 0, 0}, {W, 1, 0}, {W, 1, 1}, {W, 0, 1}});
    quad({{0, 0, 0}, {0, 1, 0}, {W, 1, 0}, {W, 0, 0}});
    quad({{0, 0, 1}, {W, 0, 1}, {W, 1, 1}, {0, 1, 1}});
    quad({{a, 1, 0}, {a, 1, 1}, {W, 1, 1}, {W, 1, 0}});  // ceiling over B
    const double hole[4][4] = {{0, 1, 0, 0.3}, {0, 1, 0.7, 1}, {0, 0.3, 0.3, 0.7}, {0.7, 1, 0.3, 0.7}};
    for (const auto& h : hole) quad({{h[0], 1, h[2]}, {h[0], 1, h[3]}, {h[1], 1, h[3]}, {h[1], 1, h[2]}});  // over A
    quad({{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}});  // the wall between: its faces and top
    if (w > 0.0) {
        quad({{a, 0, 0}, {a, 0, 1}, {a, 1, 1}, {a, 1, 0}});
        quad({{1, 1, 0}, {1, 1, 1}, {a, 1, 1}, {a, 1, 0}});
    }
    return dir / "rooms.obj";
}

// Mean and largest of the pixels' (r + g + b) / 3 over [x0, x1) × [y0, y1).
struct GreyStats {
    double mean = 0.0, largest = 0.0;
};
GreyStats greyStats(const ImageF& image, int x0, int x1, int y0, int y1) {
    GreyStats stats;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            const float* p = image.at(x, y);
            const double grey = (p[0] + p[1] + p[2]) / 3.0;
            stats.mean += grey;
            stats.largest = std::max(stats.largest, grey);
        }
    stats.mean /= double(x1 - x0) * (y1 - y0);
    return stats;
}


// One bounce cannot bring any light into room B: everything it sees is unlit. A cone from B
// must neither see room A's light through the wall, nor the sunlit top of B's own ceiling.
// Returns room B's indirect radiance over the lit floor's. `turnDegrees` turns the rooms, their
// camera and `sun` (the direction its light travels, in the rooms' own frame) about the vertical.
GreyStats closedRoomLeak(double wallVoxels, const std::string& engineOptions = "", double turnDegrees = 0.0,
                         glm::dvec3 sun = {0.3, -1.0, 0.2}) {
    const double turn = glm::radians(turnDegrees);
    const auto dir = test::testDir() / ("wall_" + std::to_string(wallVoxels) + "_turn_" + std::to_string(int(turnDegrees)));
    std::filesystem::create_directories(dir);
    const auto model = writeTwoRooms(dir, wallVoxels, turn);
    const double litFloor = 0.8 / kPi * 10.0 * -sun.y / glm::length(sun);  // ρ/π·E·cosθ
    const std::string view = "--scene " + model.string() + vectorOption("--sun-dir", aboutVertical(sun, turn)) +
                             " --sun-irradiance 10" + vectorOption("--eye", aboutVertical({1.5, 0.7, 0.03}, turn)) +
                             vectorOption("--target", aboutVertical({1.6, 0.2, 0.9}, turn)) +
                             " --fov 100 --width 96 --height 72" + engineOptions;
    const ImageF indirect = bench::subtractImages(render(dir, "b_final", view), render(dir, "b_direct", view + " --aov direct"));
    const GreyStats room = greyStats(indirect, 0, indirect.width, 0, indirect.height);
    const GreyStats leak{room.mean / litFloor, room.largest / litFloor};
    std::printf("[ leak     ] closed room, wall %.1f voxels thick, turned %.0f°%s: indirect radiance mean %.3f %%, largest "
                "pixel %.2f %% of the lit floor's\n",
                wallVoxels, turnDegrees, engineOptions.c_str(), 100.0 * leak.mean, 100.0 * leak.largest);
    return leak;
}

// A wall 8 × 5.122 m standing on a sunlit floor 40 m square: at 256³ the floor's plane lies at
// voxel height 111.8, at the top of its node of every level up to 4 voxels, so that a cone passing
// low over it samples from the empty node above it (cone_march.glsl, readsAcrossEmptyNodes).
std::filesystem::path writeWallOnAFloorAtTheTopOfItsNode(const std::filesystem::path& dir) {
    test::ObjWriter model;
    model.material("white", glm::vec3(0.8f));
    model.floor(0.0f, 20.0f);
    model.box({-4.0f, 0.0f, -0.15f}, {4.0f, 5.122f, 0.15f});
    return model.write(dir, "wall");
}

// The built-in Cornell box, its camera and its spot light turned by `degrees` about the vertical
// through the box's centre: the model written as OBJ and the options that view it. Two specks at
// opposite corners of the bounds of the box turned by 45° give every turn the same bounds, so
// that the voxels are the same size.
std::string writeTurnedCornellBox(const std::filesystem::path& dir, double degrees) {
    const Scene cornell = makeCornellBox();
    const double a = glm::radians(degrees);
    const auto turned = [&](std::uint32_t index) {
        return glm::vec3(aboutVertical(cornell.origin + glm::dvec3(cornell.vertices[index].position), a));
    };
    test::ObjWriter obj;
    for (const DrawRange& range : cornell.drawRanges) {
        const Material& material = cornell.materials[range.material];
        obj.material(material.name, material.baseColor);
        for (std::uint32_t i = range.firstIndex; i < range.firstIndex + range.indexCount; i += 3)
            obj.triangle(turned(cornell.indices[i]), turned(cornell.indices[i + 1]), turned(cornell.indices[i + 2]));
    }
    for (const glm::vec3 corner : {glm::vec3(-1.45f, 0.0f, -1.45f), glm::vec3(1.45f, 2.9f, 1.45f)})
        obj.triangle(corner, corner + glm::vec3(0.001f, 0, 0), corner + glm::vec3(0, 0.001f, 0));
    const Camera& camera = cornell.cameras.front();
    const Light& spot = cornell.lights.front();
    char rest[160];
    std::snprintf(rest, sizeof rest, " --fov %.6f --spot-intensity %.6f --spot-angles %.6f,%.6f", camera.fovYDeg,
                  spot.intensity, spot.innerAngleDeg, spot.outerAngleDeg);
    return "--scene " + obj.write(dir, "turned" + std::to_string(int(degrees))).string() +
           vectorOption("--eye", aboutVertical(camera.eye, a)) + vectorOption("--target", aboutVertical(camera.target, a)) +
           vectorOption("--spot-pos", aboutVertical(spot.position, a)) +
           vectorOption("--spot-dir", aboutVertical(spot.direction, a)) + rest;
}

}  // namespace

TEST(GiAccuracy, TurningTheSceneAboutTheVerticalKeepsItsIndirectLight) {
    // The octree's axes are the world's: a room turned by 30° or 45° meets the voxels and the
    // radiance pools' six directions at other angles than the axis-aligned one, but its light,
    // seen by a camera turned with it, is the same (the path tracer's images agree to 0.1 %).
    const auto dir = test::testDir();
    auto indirect = [&](double degrees) {
        return render(dir, "turned" + std::to_string(int(degrees)),
                      writeTurnedCornellBox(dir, degrees) + " --voxel-levels 7 --width 96 --height 72 --aov gi");
    };
    const ImageF unturned = indirect(0.0);
    for (double degrees : {30.0, 45.0}) {
        const std::string what = "Cornell box turned by " + std::to_string(int(degrees)) + "°";
        expectIndirectWithin({indirect(degrees), unturned}, what.c_str(), kTurnedMean[0], kTurnedMean[1],
                             kTurnedCells[0], kTurnedCells[1], "the unturned box's");
    }
}

TEST(GiAccuracy, NarrowConesSeeAFloorAtTheTopOfItsNode) {
    // Cones of 1.7° looking down at the floor from the wall meet it at a grazing angle, where they
    // see it only through their reads across the axis; without those reads out of the empty
    // nodes above the floor the wall got 0.41× the path tracer's light.
    const auto dir = test::testDir();
    const std::string view = "--scene " + writeWallOnAFloorAtTheTopOfItsNode(dir).string() +
                             " --sun-dir 0,-1,0 --eye 0,2.5,8 --target 0,2.5,0 --width 96 --height 54";
    const IndirectPair parts = indirectParts(dir, view, 256, " --cone-rays 16");
    // The wall's face above its foot: the middle column of a 3×3 grid, its upper two cells.
    const metrics::RegionRatios regions = metrics::regionRatios(parts.engine, parts.reference, 3, 3);
    const double ratio = (regions.cell(1, 0).meanA + regions.cell(1, 1).meanA) /
                         (regions.cell(1, 0).meanB + regions.cell(1, 1).meanB);
    std::printf("[ accuracy ] wall on a floor at the top of its node, 16 narrow cones: %.3f× the path tracer's\n", ratio);
    EXPECT_GE(ratio, kNarrowWallRatio[0]);
    EXPECT_LE(ratio, kNarrowWallRatio[1]);
}

TEST(GiAccuracy, AGalleryGetsTheLightOfASunlitFloorItSeesAtAGrazingAngle) {
    // A gallery open on one side, lit only by one bounce off the sunlit courtyard floor beside
    // it, seen from inside towards its roof and back wall: their cones see the floor at grazing
    // angles, through their reads across the axis. Reads that reached past the footprint
    // collected the floor's light while the cone was still far above it, and reads that missed
    // the floor's face counted it only in part, sample by sample.
    const auto dir = test::testDir();
    const std::string view = "--scene " + (std::filesystem::path(VCT_SOURCE_DIR) / "benchmarks/scenes/colonnade_open.obj").string() +
                             " --sun-dir 0.25,-0.968,0.1 --sun-irradiance 10 --eye 0.8,1.2,-3 --target 1.5,3.2,3 --fov 70"
                             " --width 128 --height 96";
    const IndirectPair parts = indirectParts(dir, view, 256);
    const metrics::RegionRatios regions = metrics::regionRatios(parts.engine, parts.reference, 3, 3);
    const double ratio = regions.meanA / regions.meanB;
    std::printf("[ accuracy ] gallery beside a sunlit courtyard floor: indirect %.3f× the path tracer's\n", ratio);
    EXPECT_GE(ratio, kGalleryMean[0]);
    EXPECT_LE(ratio, kGalleryMean[1]);
    // The roof and the back wall (the upper two rows); the bottom row's light is a few pixels of
    // the gallery's floor by the opening, dim and noisy at this size.
    for (const metrics::RegionCell& cell : regions.cells) {
        if (cell.row == 2 || !cell.significant || !cell.ratio) continue;
        EXPECT_GE(*cell.ratio, kGalleryCells[0]) << "cell " << cell.column << "," << cell.row;
        EXPECT_LE(*cell.ratio, kGalleryCells[1]) << "cell " << cell.column << "," << cell.row;
    }
}

TEST(GiAccuracy, TheNearFieldSeesTheLitSideOfAFinTheCameraSeesFromBehind) {
    // A fin two voxels tall stands on a floor, lit by the sun on the side facing away from the
    // camera, which looks down over it at the floor beyond. Near the fin that floor's light off it
    // comes from within the cones' start offset: the near field's rays meet the fin from its lit
    // side, which the G-buffer does not hold (it holds the dark side): its light comes from the
    // voxels. Further away the cones that leave the floor at a grazing angle must start low
    // enough not to pass over the fin.
    const auto dir = test::testDir();
    test::ObjWriter model;
    model.material("floor", glm::vec3(0.5f));
    model.floor(0.0f, 4.0f);
    model.material("fin", glm::vec3(0.8f));
    model.quad({0.06f, 0.0f, -2.0f}, {0.06f, 0.25f, -2.0f}, {0.06f, 0.25f, 2.0f}, {0.06f, 0.0f, 2.0f});
    const std::string view = "--scene " + model.write(dir, "fin").string() +
                             " --sun-dir -0.6,-0.8,0 --sun-irradiance 10 --eye -2,3,0.5 --target 0.4,0,0 --fov 25"
                             " --width 96 --height 54";
    // 64³ over the 8 m floor: voxels of 0.125 m, the fin two of them tall.
    const IndirectPair parts = indirectParts(dir, view, 512, " --voxel-levels 6");
    // The floor beyond the fin, within a metre of it: the top row of a 3×3 grid (the fin's dark
    // face crosses the middle row).
    const metrics::RegionRatios regions = metrics::regionRatios(parts.engine, parts.reference, 3, 3);
    double engine = 0.0, reference = 0.0;
    for (const metrics::RegionCell& cell : regions.cells)
        if (cell.row == 0) engine += cell.meanA, reference += cell.meanB;
    std::printf("[ accuracy ] floor beside a fin lit on its far side: indirect %.3f× the path tracer's\n", engine / reference);
    EXPECT_GE(engine / reference, kFinFloorAtLeast);
    EXPECT_LE(engine / reference, 1.1);
}

TEST(GiAccuracy, EveryNarrowConeOfAPixelKeepsItsLight) {
    // 8 and 32 narrow cones estimate the same irradiance. (Traced in one invocation, the cones past
    // the first fifteen or so lost their light on llvmpipe: cone_trace.hpp, kNarrowConesPerDispatch.)
    // At 128×96, where the ratio stays within ±0.025 over the directions' seeds (at 64×48: ±0.06).
    const auto dir = test::testDir();
    const std::string view = "--scene cornell --width 128 --height 96 --aov indirect";
    const metrics::RegionRatios few = metrics::regionRatios(render(dir, "few", view + " --cone-rays 8"),
                                                            render(dir, "many", view + " --cone-rays 32"), 1, 1);
    const double ratio = few.meanB / few.meanA;
    std::printf("[ accuracy ] Cornell, 32 narrow cones against 8: %.4f× the irradiance\n", ratio);
    EXPECT_NEAR(ratio, 1.0, kNarrowConeCountTolerance);
}

TEST(GiAccuracy, ClosedRoomBesideASunlitOneStaysDark) {
    const GreyStats leak = closedRoomLeak(1.3);
    EXPECT_LE(leak.mean, kLeakMean);
    EXPECT_LE(leak.largest, kLeakLargestPixel);
}

TEST(GiAccuracy, NarrowConesKeepAClosedRoomBesideASunlitOneDark) {
    // Narrow cones read the voxels, which do not know where in them their surface lies: cones
    // from the closed room's back wall, just under its ceiling whose top is sunlit, travel inside
    // the ceiling's layer of voxels. Reading the light of the voxel they were in (a ceiling
    // voxel's light leaves upwards, seen by a cone going down) they saw that top as if it lay
    // below them: 8 % of the lit floor's radiance at single pixels with 16 cones, 3 % with 4 at a
    // step of a whole diameter. Until a cone leaves the layer it starts in along an axis it sees
    // its own voxel's light along that axis only where the voxel's photons landed ahead of it
    // (cone_march.glsl, sampleVoxels; facing.glsl, litPlace).
    for (const char* cones : {" --cone-rays 16", " --cone-rays 4 --cone-step 1"}) {
        const GreyStats leak = closedRoomLeak(1.3, cones);
        EXPECT_LE(leak.mean, kLeakMean) << cones;
        EXPECT_LE(leak.largest, kLeakLargestPixel) << cones;
    }
}

TEST(GiAccuracy, ASheetBetweenASunlitRoomAndAClosedOneKeepsItDarkForNarrowConesToo) {
    const GreyStats leak = closedRoomLeak(0.0, " --cone-rays 4 --cone-step 1");
    EXPECT_LE(leak.mean, kLeakMean);
    EXPECT_LE(leak.largest, kSheetLargestPixel);
}

TEST(GiAccuracy, ASheetBetweenASunlitRoomAndAClosedOneKeepsItDark) {
    // A curtain-like wall of no thickness: both of its sides lie in the same voxels.
    const GreyStats leak = closedRoomLeak(0.0);
    EXPECT_LE(leak.mean, kLeakMean);
    EXPECT_LE(leak.largest, kSheetLargestPixel);
}

TEST(GiAccuracy, AClosedRoomTurnedToTheGridLeaksNoMoreThanItsKnownLimit) {
    // A guard on a known leak (frame.md, Known limits): the rooms turned 45° to the grid, room B's
    // end wall (a sheet) lit from outside by a low sun. One bounce brings room B nothing; the
    // bricks still let some of the wall's lit side through, about half of what they did before the
    // exit shares were signed on the dark side (radiance_normalize.comp, darkSideSigned).
    const GreyStats leak = closedRoomLeak(0.0, "", 45.0, {-0.95, -0.3, 0.0});
    EXPECT_LE(leak.mean, kTurnedRoomLeakMean);
    EXPECT_LE(leak.largest, kTurnedRoomLeakLargestPixel);
}

TEST(GiAccuracy, ASheetAtAnAngleToTheGridShowsItsLightOnItsLitSideOnly) {
    // A sheet 2 m square standing at 45° to the x and z axes, lit by a low sun on the side facing
    // +x and −z. The voxels' light seen from its other side at a grazing angle (`--view radiance`:
    // what each voxel sends towards the eye, mixed over the axes as a cone mixes them) must be
    // nothing: read along z alone, the lit side's share towards −z showed a ray that travels +x
    // and +z, coming from the dark side, half the light the lit side shows at that angle
    // (radiance_normalize.comp, darkSideSigned).
    const auto dir = test::testDir() / "turned_sheet";
    std::filesystem::create_directories(dir);
    const glm::vec3 litSide = glm::normalize(glm::vec3(1.0f, 0.0f, -1.0f)), along = glm::normalize(glm::vec3(1.0f, 0.0f, 1.0f));
    const glm::vec3 centre(0.0f, 1.0f, 0.0f), up(0.0f, 1.0f, 0.0f);
    test::ObjWriter model;
    model.material("white", glm::vec3(0.8f));
    model.quad(centre - along - up, centre + along - up, centre + along + up, centre - along + up);
    const std::string scene = "--scene " + model.write(dir, "sheet").string() +
                              " --sun-dir -0.6718,-0.3,0.6718 --sun-irradiance 10 --target 0,1,0 --fov 60 --width 64 "
                              "--height 48 --view radiance";
    const auto seenFrom = [&](const std::string& name, glm::vec3 eye) {
        return greyStats(render(dir, name, scene + vectorOption("--eye", glm::dvec3(eye))), 0, 64, 0, 48);
    };
    const GreyStats lit = seenFrom("lit", centre + 2.0f * litSide);
    const GreyStats darkLeft = seenFrom("dark_left", centre - 0.5f * litSide - 2.0f * along);
    const GreyStats darkRight = seenFrom("dark_right", centre - 0.5f * litSide + 2.0f * along);
    std::printf("[ leak     ] sheet at 45° to the grid: voxels' light seen from its lit side %.3f, from its dark side "
                "%.5f and %.5f (largest pixel %.5f)\n",
                lit.mean, darkLeft.mean, darkRight.mean, std::max(darkLeft.largest, darkRight.largest));
    EXPECT_GT(lit.mean, 0.5);  // the lit side is seen, and lit
    EXPECT_LE(std::max(darkLeft.largest, darkRight.largest), 1e-4 * lit.mean);
}

TEST(GiAccuracy, TwoLightsGiveTheSumOfTheirIndirectLight) {
    // Light adds up: the sun outside a room of walls of no thickness (through a hole in its roof)
    // and a point light inside it. Each wall voxel holds both faces, lit outside by the sun and
    // inside by the lamp with far less flux per photon; its light must leave each side in
    // proportion to the flux that side received (photons counted alike sent half the sun's light
    // into the room: 4.4× the sum).
    const auto dir = test::testDir();
    const std::string view = "--scene " + (std::filesystem::path(VCT_SOURCE_DIR) / "benchmarks/scenes/lamp_room.obj").string() +
                             " --eye 0,2,1.9 --target 0,1.5,-2 --fov 80 --width 80 --height 45 --aov gi";
    const std::string sun = " --sun-dir 0.15,-1,0.1 --sun-irradiance 10",
                      lamp = " --point-pos 1.5,3.5,1.5 --point-intensity 2";
    const double sunOnly = test::meanRgb(render(dir, "sun", view + sun)), lampOnly = test::meanRgb(render(dir, "lamp", view + lamp));
    const double both = test::meanRgb(render(dir, "both", view + sun + lamp));
    std::printf("[ lights   ] indirect mean: sun %.5f, lamp %.5f, both %.5f (%.3f× their sum)\n", sunOnly, lampOnly, both,
                both / (sunOnly + lampOnly));
    EXPECT_GT(sunOnly, 0.0);
    EXPECT_GT(lampOnly, 0.0);
    EXPECT_NEAR(both, sunOnly + lampOnly, 0.02 * (sunOnly + lampOnly));
}

TEST(GiAccuracy, AFloorUnderASheetSeesNoneOfTheEmitterAboveIt) {
    // Three parallel squares 4 m wide: a floor, a sheet 1 m above it and an emitter (Le = 1) 3.5 m
    // up. From the middle of the floor every upward ray meets the sheet's unlit underside, so its
    // one-bounce indirect light is 0. The cones cross the empty space under the sheet at coarse
    // levels: a sample whose own node is empty must still read the sheet's slab ahead of it, or
    // whether a cone sees the sheet depends on where its samples fall and it passes through.
    const auto dir = test::testDir();
    test::ObjWriter obj;
    obj.material("white", glm::vec3(0.5f));
    obj.floor(0.0f, 2.0f);
    obj.floor(1.0f, 2.0f);
    obj.material("emitter", glm::vec3(0.5f), glm::vec3(1.0f));
    obj.floor(3.5f, 2.0f);
    const auto model = obj.write(dir);
    // Narrow cones too, with their step of a whole diameter (`--cone-step 1`): a sheet inside its
    // voxels lay partly in the window a sample reads from an empty node and partly in the next
    // one's, and was counted by a third to three quarters (cone_march.glsl, sampleVoxels and
    // slabAheadOfEmpty): 2.7 % of pi*Le at 256³.
    for (const char* cones : {"", " --cone-rays 4 --cone-step 1"})
        for (int levels : {6, 7, 8}) {
            const ImageF indirect = render(dir, "sheet" + std::to_string(levels),
                                           "--scene " + model.string() + " --voxel-levels " + std::to_string(levels) +
                                               " --eye 0.05,0.6,0.07 --target 0.05,0,0.0701 --fov 90 --width 64"
                                               " --height 64 --aov indirect --gi-resolution full" + cones);
            const GreyStats middle = greyStats(indirect, 16, 48, 16, 48);
            const double full = kPi * 1.0;  // E of a floor that saw the emitter everywhere
            std::printf("[ leak     ] floor under a sheet, %d levels%s: irradiance mean %.2f %%, largest %.2f %% of pi*Le\n",
                        levels, cones, 100.0 * middle.mean / full, 100.0 * middle.largest / full);
            EXPECT_LE(middle.mean, kUnderSheetMean * full) << levels << " levels" << cones;
            EXPECT_LE(middle.largest, kUnderSheetLargestPixel * full) << levels << " levels" << cones;
        }
}

TEST(GiAccuracy, AThinSlabSendsTheLightOfItsLitFaceLikeASheet) {
    // A wall 5 mm thick (a curtain or banner modelled with both faces), far thinner than a voxel
    // (3 cm), lit by the sun on its front face, beside a sunlit floor: the floor sees only the lit
    // face, as it would of a wall of no thickness. Each voxel of the slab holds both faces, lit and
    // dark, so its mean radiance is half the lit face's; a voxel must still send the light of its
    // lit face towards the side that face looks to (radiance_normalize.comp), or the slab lights
    // the floor half as much as the sheet (0.51 with the cone set and 0.50 with narrow cones when
    // each voxel had one mean lit normal and sent its mean radiance).
    const auto dir = test::testDir();
    auto floorIndirect = [&](bool slab, const std::string& cones) {
        test::ObjWriter obj;
        obj.material("white", glm::vec3(0.6f));
        obj.quad({-2.0f, 0.0f, 0.0f}, {2.0f, 0.0f, 0.0f}, {2.0f, 0.0f, 3.0f}, {-2.0f, 0.0f, 3.0f});  // floor
        obj.quad({-2.0f, 0.0f, 0.0f}, {2.0f, 0.0f, 0.0f}, {2.0f, 3.0f, 0.0f}, {-2.0f, 3.0f, 0.0f});  // front face
        if (slab) obj.quad({-2.0f, 0.0f, -0.005f}, {2.0f, 0.0f, -0.005f}, {2.0f, 3.0f, -0.005f}, {-2.0f, 3.0f, -0.005f});
        const auto model = obj.write(dir, slab ? "slab" : "sheet");
        const ImageF gi = render(dir, (slab ? "slab" : "sheet") + std::to_string(cones.size()),
                                 "--scene " + model.string() + " --voxel-levels 7 --sun-dir 0.2,-0.6,-1 " + cones +
                                     " --eye 0,2.2,3.4 --target 0,0.2,1.0 --fov 50 --width 64 --height 48"
                                     " --aov gi --gi-resolution full");
        return greyStats(gi, 0, 64, 24, 48).mean;  // the lower half: the floor in front of the wall
    };
    for (const std::string cones : {"", "--cone-rays 16"}) {
        const double sheet = floorIndirect(false, cones), slab = floorIndirect(true, cones);
        std::printf("[ slab     ] floor's indirect light beside a slab / beside a sheet (%s): %.3f\n",
                    cones.empty() ? "cone set" : "narrow cones", slab / sheet);
        ASSERT_GT(sheet, 0.0);
        EXPECT_NEAR(slab / sheet, 1.0, kSlabLikeSheetTolerance) << cones;
    }
}

TEST(GiAccuracy, WhiteFurnaceGetsOneBounce) {
    // A closed box whose walls (albedo 0.5) emit Le = 1: with one bounce every wall shows
    // Le + ρ·Le = 1.5, whatever the view (the reference's furnace test checks the same series).
    // Every cone meets a wall, so this measures the energy the cones lose on their way, and the
    // indirect light alone (the gi AOV, ρ·Le = 0.5) must never exceed what the furnace holds. The
    // default sun outside lights the walls' outer faces; what of it the shadow map lets in along
    // the seams is the next test's.
    const auto dir = test::testDir();
    const auto model = test::writeFurnace(dir, 0.5f, 1.0f);
    const ImageF image = render(dir, "furnace", "--scene " + model.string() + test::kInsideFurnace);
    std::vector<double> pixels;
    for (std::size_t i = 0; i < image.rgba.size(); i += 4)
        pixels.push_back((image.rgba[i] + image.rgba[i + 1] + image.rgba[i + 2]) / 3.0);
    std::sort(pixels.begin(), pixels.end());
    double sum = 0.0;
    for (double p : pixels) sum += p;
    const double mean = sum / double(pixels.size()), low = pixels[pixels.size() / 20];
    const ImageF gi = render(dir, "furnace_gi", "--scene " + model.string() + test::kInsideFurnace + " --aov gi");
    double giLargest = 0.0;
    for (std::size_t i = 0; i < gi.rgba.size(); i += 4)
        giLargest = std::max(giLargest, (gi.rgba[i] + gi.rgba[i + 1] + gi.rgba[i + 2]) / 3.0);
    std::printf("[ furnace  ] one bounce: mean %.4f (1.5 expected), 5th percentile %.4f; indirect largest %.4f (0.5)\n",
                mean, low, giLargest);
    EXPECT_NEAR(mean, 1.5, kFurnaceMeanTolerance * 1.5);
    EXPECT_GE(low, (1.0 - kFurnaceLowTolerance) * 1.5);
    EXPECT_LE(giLargest, 0.5 * 1.01);
}

TEST(GiAccuracy, SunReachesTheInsideOfAClosedBoxOnlyAlongItsSeams) {
    // The furnace's direct light (emission Le = 1 plus the sun, which lights only its outer faces)
    // from five views: inside, the sun can only come through the shadow map's filter where a wall
    // meets the wall it shades (frame.md, Known limits). A guard on that known leak: rare, small on
    // average, bounded at its worst pixel. The symmetric view of the test above puts its corner
    // pixels' centres exactly on two seams, where the rasterizer's tie-breaking picks the wall
    // (an NVIDIA driver the other wall than llvmpipe, and 0.28 of leak there).
    const auto dir = test::testDir();
    const auto model = test::writeFurnace(dir, 0.5f, 1.0f);
    const char* views[] = {"--eye 0,0,0.5 --target 0,0,-1 --fov 70", "--eye 0.013,0.021,0.5 --target 0,0,-1 --fov 70",
                           "--eye 0.5,0.5,0.5 --target -1,-1,-1 --fov 90", "--eye -0.4,-0.3,0.2 --target 1,0.8,-1 --fov 80",
                           "--eye 0.3,-0.5,-0.2 --target -1,1,1 --fov 75"};
    for (int v = 0; v < 5; ++v) {
        const ImageF direct = render(dir, "seams" + std::to_string(v),
                                     "--scene " + model.string() + " " + views[v] + " --width 96 --height 96 --aov direct");
        double sum = 0.0, largest = 0.0;
        std::size_t leaking = 0, count = 0;
        for (std::size_t i = 0; i < direct.rgba.size(); i += 4, ++count) {
            const double excess = (direct.rgba[i] + direct.rgba[i + 1] + direct.rgba[i + 2]) / 3.0 - 1.0;
            sum += excess;
            largest = std::max(largest, excess);
            leaking += excess > 0.01;
        }
        const double mean = sum / double(count), share = double(leaking) / double(count);
        std::printf("[ seams    ] view %d: sun inside the box: mean %.5f, %.2f %% of the pixels above 0.01, largest %.3f\n", v,
                    mean, 100.0 * share, largest);
        EXPECT_GE(mean, -1e-4) << views[v] << ": the walls' emission must come through";
        EXPECT_LE(mean, kSeamLeakMean) << views[v];
        EXPECT_LE(share, kSeamLeakPixelShare) << views[v];
        EXPECT_LE(largest, kSeamLeakLargest) << views[v];
    }
}

TEST(GiAccuracy, WhiteFurnaceGetsMoreBounces) {
    // The same furnace with 2 and 3 bounces: Le (1 + ρ + ρ²) = 1.75 and 1.875. Each gather loses
    // what one bounce loses (the test above), and the losses compound. Then a furnace whose walls
    // are solid slabs: the side of a voxel that faces into a wall gathers nothing, but the inner
    // faces lie on cell faces, in two cells each, and neither may lose its bounces (the cell in
    // the wall faces the other; when it gathers for both, the other must still get its light).
    const auto dir = test::testDir();
    const std::filesystem::path models[2] = {test::writeFurnace(dir, 0.5f, 1.0f),
                                             test::writeThickWalledFurnace(dir, 0.5f, 1.0f, 10.0f / 246.0f)};
    const std::string views[2] = {test::kInsideFurnace, " --eye 0,0.5,0 --target 0,-1,0.01 --fov 70 --width 24 --height 24 "};
    const double expected[2] = {1.75, 1.875};
    for (int m = 0; m < 2; ++m)
        for (int bounces : {2, 3}) {
            const ImageF image = render(dir, "furnace" + std::to_string(m) + std::to_string(bounces),
                                        "--scene " + models[m].string() + views[m] + " --bounces " + std::to_string(bounces));
            double sum = 0.0, smallest = 1e30;
            for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
                const double pixel = (image.rgba[i] + image.rgba[i + 1] + image.rgba[i + 2]) / 3.0;
                sum += pixel;
                smallest = std::min(smallest, pixel);
            }
            const double mean = sum / (double(image.width) * image.height), want = expected[bounces - 2];
            std::printf("[ furnace  ] %s walls, %d bounces: mean %.4f, smallest %.4f (%.4f expected, %+.1f %%)\n",
                        m == 0 ? "thin" : "thick", bounces, mean, smallest, want, 100.0 * (mean / want - 1.0));
            EXPECT_NEAR(mean, want, kFurnaceBouncesTolerance * want) << bounces << " bounces, model " << m;
            EXPECT_LT(mean, want * 1.01) << "more light than the series holds";
            // (The thin box's corners are darker: its seams, frame.md Known limits.)
            if (m == 1) EXPECT_GT(smallest, want * (1.0 - kFurnaceBouncesTolerance)) << bounces << " bounces";
        }
}

TEST(GiAccuracy, MoreBouncesFollowThePathTracerOnCornell) {
    const auto dir = test::testDir();
    const std::string view = "--scene cornell --width 96 --height 72 --bounces 2";
    const ImageF final = render(dir, "final", view), direct = render(dir, "direct", view + " --aov direct");
    const auto full = dir / "reference.pfm", referenceDirect = dir / "reference_direct.pfm";
    const test::CommandResult r = test::runVct("reference -q " + view + " --spp 512 -o " + full.string() +
                                               " --direct-out " + referenceDirect.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const IndirectPair parts{bench::subtractImages(final, direct), bench::subtractImages(readHdrImage(full), readHdrImage(referenceDirect))};
    expectIndirectWithin(parts, "Cornell 96x72, 2 bounces", kCornellMean[0], kCornellMean[1], kCornellCells[0],
                         kCornellCells[1]);
}

TEST(GiAccuracy, FurtherBouncesThroughAnOpeningMatchThePathTracer) {
    // Two rooms under a roof over one of them, the sun straight down into the other: everything
    // the roofed room receives comes through the opening between them, and the bounces after the
    // first are light its own walls, floor and ceiling pass on to each other. The further bounces
    // are the 3-bounce image less the 1-bounce one, engine and path tracer alike. Gathered with
    // the cone set, they came to 0.64× the path tracer's (render/cone_trace.hpp, kDefaultBounceRays).
    const auto dir = test::testDir();
    const std::string view =
        "--scene " + (std::filesystem::path(VCT_SOURCE_DIR) / "benchmarks/scenes/two_rooms_no_wall.obj").string() +
        " --sun-dir 0,-1,0.05 --sun-irradiance 10 --eye 4.3,2,0 --target 8,1.5,0 --fov 70 --width 96 --height 54";
    double engine[2], traced[2];
    for (int i = 0; i < 2; ++i) {
        const std::string bounces = i == 0 ? "1" : "3";
        engine[i] = test::meanRgb(render(dir, "engine" + bounces, view + " --bounces " + bounces));
        const auto out = dir / ("reference" + bounces + ".pfm");
        const test::CommandResult r =
            test::runVct("reference -q " + view + " --spp 64 --bounces " + bounces + " -o " + out.string());
        ASSERT_EQ(r.exitCode, 0) << r.output;
        traced[i] = test::meanRgb(readHdrImage(out));
    }
    const double further = (engine[1] - engine[0]) / (traced[1] - traced[0]);
    std::printf("[ accuracy ] two rooms, bounces 2 and 3: %.3f× the path tracer's (first bounce %.3f×)\n", further,
                engine[0] / traced[0]);
    EXPECT_GE(further, kFurtherBounces[0]);
    EXPECT_LE(further, kFurtherBounces[1]);
}

TEST(GiAccuracy, IndirectLightMatchesThePathTracerOnCornell) {
    const auto dir = test::testDir();
    const IndirectPair parts = indirectParts(dir, "--scene cornell --width 96 --height 72", 512);
    expectIndirectWithin(parts, "Cornell 96x72", kCornellMean[0], kCornellMean[1], kCornellCells[0], kCornellCells[1]);
}

TEST(GiAccuracy, TheConeSetStaysWithinItsBoundsOnCornell) {
    const IndirectPair parts = indirectParts(test::testDir(), "--scene cornell --width 96 --height 72", 512, " --cone-rays 0");
    expectIndirectWithin(parts, "Cornell 96x72, the cone set", kConeSetCornellMean[0], kConeSetCornellMean[1],
                         kConeSetCornellCells[0], kConeSetCornellCells[1]);
}

TEST(GiAccuracy, PointLitCornellMatchesThePathTracer) {
    // A point light inside the box: six light-view maps (cube faces) serve as shadow map and
    // photon source. Direct light is exact up to pixel sampling; the indirect part is held to
    // the same bounds as the spot-lit box.
    const auto dir = test::testDir();
    const std::string view = "--scene cornell --width 160 --height 120 --point-pos 0,1.5,0 --point-intensity 3";
    const ImageF direct = render(dir, "direct", view + " --aov direct");
    const auto full = dir / "reference.pfm", referenceDirect = dir / "reference_direct.pfm";
    const test::CommandResult r = test::runVct("reference -q " + view + " --bounces 1 --spp 512 -o " + full.string() +
                                               " --direct-out " + referenceDirect.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const ImageF reference = readHdrImage(full), referenceDirectImage = readHdrImage(referenceDirect);
    const metrics::RegionRatios directRegions = metrics::regionRatios(direct, referenceDirectImage, 1, 1);
    const double directRatio = directRegions.meanA / directRegions.meanB;
    std::printf("[ accuracy ] point-lit Cornell: direct %.4f× the path tracer's\n", directRatio);
    EXPECT_NEAR(directRatio, 1.0, 0.01);
    const IndirectPair parts{bench::subtractImages(render(dir, "final", view), direct), bench::subtractImages(reference, referenceDirectImage)};
    expectIndirectWithin(parts, "point-lit Cornell 160x120", kCornellMean[0], kCornellMean[1], kCornellCells[0],
                         kCornellCells[1]);
}

TEST(GiAccuracy, NarrowConesMatchThePathTracerOnCornell) {
    const auto dir = test::testDir();
    const IndirectPair parts = indirectParts(dir, "--scene cornell --width 96 --height 72", 512, " --cone-rays 16");
    expectIndirectWithin(parts, "Cornell 96x72, 16 narrow cones", kNarrowMean[0], kNarrowMean[1], kNarrowCells[0],
                         kNarrowCells[1]);
}

TEST(GiAccuracy, AccumulatedSamplesConvergeToTheNarrowCones) {
    // `--samples 16`: the first sample traces the cone set, the fifteen after it one narrow cone
    // per traced pixel each (render/cone_trace.hpp, conesForSample). Their average has the narrow
    // cones' small bias and removes most of their noise; sixteen samples of the cone set keep its bias.
    const auto dir = test::testDir();
    const std::string view = "--scene cornell --width 96 --height 72";
    const IndirectPair narrow = indirectParts(dir, view, 512, " --samples 16");
    expectIndirectWithin(narrow, "Cornell 96x72, 16 samples (narrow cones after the first)", kNarrowMean[0],
                         kNarrowMean[1], kNarrowCells[0], kNarrowCells[1]);
    const std::string setOptions = view + " --samples 16 --cone-rays 0 --sample-cones frame";
    const ImageF set = bench::subtractImages(render(dir, "set_final", setOptions),
                                             render(dir, "set_direct", setOptions + " --aov direct"));
    const double narrowError = metrics::rmse(narrow.engine, narrow.reference);
    const double setError = metrics::rmse(set, narrow.reference);  // the same reference
    std::printf("[ accuracy ] Cornell 96x72, 16 samples: indirect RMSE %.4f with narrow cones after the first, "
                "%.4f with the cone set at every sample\n",
                narrowError, setError);
    EXPECT_LT(narrowError, kAccumulatedNarrowErrorShare * setError);
}

TEST(GiAccuracy, NarrowConesMatchThePathTracerOnSponza) {
    const test::CommandResult found = test::runVct("info --scene sponza");
    if (found.exitCode != 0) GTEST_SKIP() << "Sponza is not in the asset search path: " << found.output;
    const auto dir = test::testDir();
    const IndirectPair parts =
        indirectParts(dir, "--scene sponza --camera CameraMain --width 96 --height 54", 256, " --cone-rays 16");
    expectIndirectWithin(parts, "Sponza CameraMain 96x54, 16 narrow cones", kNarrowMean[0], kNarrowMean[1],
                         kNarrowCells[0], kNarrowCells[1]);
}

TEST(GiAccuracy, NarrowConesSeeTheSecondBounceInTheVoxels) {
    // Narrow cones thinner than a voxel read the voxels; after a further bounce the voxels they read
    // hold it too (RadianceVolume::bouncedCellRadiance). When they held only the first bounce and
    // narrow cones read the blurred leaf bricks instead, the second bounce's light came out at
    // 0.54× the path tracer's here: the switch lost more first-bounce light than the bounce added.
    const test::CommandResult found = test::runVct("info --scene sponza");
    if (found.exitCode != 0) GTEST_SKIP() << "Sponza is not in the asset search path: " << found.output;
    const auto dir = test::testDir();
    const std::string view = "--scene sponza --camera CameraMain --width 96 --height 54";
    auto reference = [&](int bounces) {
        const auto out = dir / ("reference" + std::to_string(bounces) + ".pfm");
        const test::CommandResult r = test::runVct("reference -q " + view + " --spp 256 --bounces " +
                                                   std::to_string(bounces) + " -o " + out.string());
        EXPECT_EQ(r.exitCode, 0) << r.output;
        return readHdrImage(out);
    };
    auto engine = [&](int bounces) {
        return render(dir, "narrow" + std::to_string(bounces),
                      view + " --cone-rays 16 --bounces " + std::to_string(bounces));
    };
    const double referenceSecond = test::meanRgb(bench::subtractImages(reference(2), reference(1)));
    const double engineSecond = test::meanRgb(bench::subtractImages(engine(2), engine(1)));
    const double ratio = engineSecond / referenceSecond;
    std::printf("[ accuracy ] Sponza CameraMain 96x54, 16 narrow cones: the second bounce %.3f× the path tracer's\n", ratio);
    EXPECT_GE(ratio, kNarrowSecondBounce[0]);
    EXPECT_LE(ratio, kNarrowSecondBounce[1]);
}

TEST(GiAccuracy, SponzaUnderOtherSunsStaysWithinItsKnownLimits) {
    const test::CommandResult found = test::runVct("info --scene sponza");
    if (found.exitCode != 0) GTEST_SKIP() << "Sponza is not in the asset search path: " << found.output;
    const auto dir = test::testDir();
    for (const char* sun : {"-0.2822,-0.9407,-0.1881", "0.7,-0.65,-0.2"}) {
        const std::string view = std::string("--scene sponza --camera CameraMain --width 128 --height 72 --sun-dir ") +
                                 sun + " --sun-irradiance 10";
        const IndirectPair parts = indirectParts(dir, view, 256);
        expectIndirectWithin(parts, (std::string("Sponza CameraMain 128x72, sun ") + sun).c_str(), kOtherSunMean[0],
                             kOtherSunMean[1], kOtherSunCells[0], kOtherSunCells[1]);
    }
}

TEST(GiAccuracy, IndirectLightMatchesThePathTracerOnSponza) {
    const test::CommandResult found = test::runVct("info --scene sponza");
    if (found.exitCode != 0) GTEST_SKIP() << "Sponza is not in the asset search path: " << found.output;
    const auto dir = test::testDir();
    // 128×72: at 96×54 a cell holds about 600 narrow cones, and its ratio moved by ±0.15 with the
    // seed of their directions (the largest cell 1.19..1.62 over four seeds); here 1.17..1.29.
    const IndirectPair parts = indirectParts(dir, "--scene sponza --camera CameraMain --width 128 --height 72", 256);
    expectIndirectWithin(parts, "Sponza CameraMain 128x72", kSponzaMean[0], kSponzaMean[1], kSponzaCells[0], kSponzaCells[1]);
}
