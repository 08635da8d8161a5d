// `vct`: the command-line front end. Errors a user can fix end as one line "vct: error: …" and
// exit code 1; usage errors exit with 2.
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "cli/commands.hpp"
#include "core/error.hpp"
#include "core/log.hpp"

int main(int argc, char** argv) {
    using namespace vct;
    if (const char* level = std::getenv("VCT_LOG")) {
        if (!std::strcmp(level, "quiet")) setLogLevel(LogLevel::Quiet);
        if (!std::strcmp(level, "warn")) setLogLevel(LogLevel::Warn);
    }
    CLI::App app{"vct: real-time global illumination by voxel cone tracing over a sparse voxel octree"};
    app.require_subcommand(1);
    app.fallthrough();  // global options (-q) may also follow the subcommand
    bool quiet = false;
    app.add_flag("-q,--quiet", quiet, "only warnings and errors on stderr, no timing table");
    cli::Run render = cli::addRenderCommand(app);
    cli::Run info = cli::addInfoCommand(app);
    cli::Run reference = cli::addReferenceCommand(app);
    cli::Run compare = cli::addCompareCommand(app);
    cli::Run view = cli::addViewCommand(app);
    cli::Run bench = cli::addBenchCommand(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return code == 0 ? 0 : 2;
    }
    if (quiet) setLogLevel(LogLevel::Warn);
    try {
        if (app.got_subcommand("render")) render();
        if (app.got_subcommand("info")) info();
        if (app.got_subcommand("reference")) reference();
        if (app.got_subcommand("compare")) compare();
        if (app.got_subcommand("view")) view();
        if (app.got_subcommand("bench")) bench();
    } catch (const Error& e) {
        std::fprintf(stderr, "vct: error: %s\n", e.what());
        return 1;
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "vct: error: out of memory; lower the resolution or use a smaller scene\n");
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "vct: error: %s (unexpected: please report it)\n", e.what());
        return 1;
    }
    return 0;
}
