#pragma once
// Runs a small compute shader of a test against the engine's own GLSL: the includes it names are
// copied from the shader directory beside it, and it runs once per case over a buffer of cases
// bound at SSBO_CONE_COUNTERS (`uCount` cases, 64 per work group), which it may rewrite.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <string>
#include <vector>

#include "gl/compute.hpp"
#include "gl/shader.hpp"
#include "svo_readback.hpp"
#include "test_util.hpp"

namespace vct::test {

// Needs a current GL context. `source` is the whole shader, `name` its file name.
template <class Case>
std::vector<Case> runShaderProbe(const std::string& name, std::initializer_list<const char*> includes,
                                 const std::string& source, const std::vector<Case>& cases) {
    const auto dir = testDir();
    for (const char* include : includes)
        std::filesystem::copy_file(gl::shaderDirectory() / include, dir / include,
                                   std::filesystem::copy_options::overwrite_existing);
    std::ofstream(dir / name) << source;
    setenv("VCT_SHADER_DIR", dir.c_str(), 1);
    const gl::Program program = gl::buildProgram({{GL_COMPUTE_SHADER, name}});
    unsetenv("VCT_SHADER_DIR");
    const gl::Buffer buffer = gl::createBuffer(GLsizeiptr(cases.size() * sizeof(Case)), cases.data(),
                                               GL_DYNAMIC_STORAGE_BIT, "shader probe cases");
    gl::ComputeCall(program)
        .storage(gl::SSBO_CONE_COUNTERS, buffer)
        .uniform("uCount", unsigned(cases.size()))
        .dispatch1D(cases.size(), 64, GL_BUFFER_UPDATE_BARRIER_BIT);
    return readBuffer<Case>(buffer, cases.size());
}

}  // namespace vct::test
