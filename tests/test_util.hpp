#pragma once
// Helpers shared by the tests: a fresh temporary folder per test and running the real `vct`
// command in a subprocess with its exit code and combined output.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>

namespace vct::test {

// A folder under the system temp dir named after the running test, emptied at construction.
inline std::filesystem::path testDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string(info->test_suite_name()) + "." + info->name();
    for (char& c : name)
        if (c == '/') c = '_';
    auto dir = std::filesystem::temp_directory_path() / "vct_tests" / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

struct CommandResult {
    int exitCode = -1;
    std::string output;  // stdout and stderr together
};

// Runs `vct <arguments>` through the shell; arguments are passed verbatim. `environment` is
// prefixed to the command ("NAME=value ...").
inline CommandResult runVct(const std::string& arguments, const std::string& environment = "") {
    const std::string command = environment + " " + std::string(VCT_BINARY) + " " + arguments + " 2>&1";
    CommandResult result;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return result;
    char buffer[4096];
    while (size_t n = fread(buffer, 1, sizeof buffer, pipe)) result.output.append(buffer, n);
    const int status = pclose(pipe);
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    return result;
}

}  // namespace vct::test
