#pragma once
// The subcommands of `vct`. Each registers its options on the app and returns the function that
// runs it once parsing succeeded.
#include <functional>

#include <CLI/CLI.hpp>

namespace vct::cli {

using Run = std::function<void()>;

Run addRenderCommand(CLI::App& app);
Run addInfoCommand(CLI::App& app);
Run addReferenceCommand(CLI::App&);
Run addCompareCommand(CLI::App&);
Run addViewCommand(CLI::App&);
Run addBenchCommand(CLI::App&);

}  // namespace vct::cli
