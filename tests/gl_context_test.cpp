// Context creation on every headless backend, and shader loading (includes, error mapping).
#include <cstdlib>
#include <fstream>

#include "core/error.hpp"
#include "gl/context.hpp"
#include "gl/shader.hpp"
#include "gl/shader_interface.hpp"
#include "test_util.hpp"

using namespace vct;

TEST(GlContext, OSMesaGives45Core) {
    auto context = gl::createContext(gl::Backend::OSMesa);
    const auto& info = context->info();
    EXPECT_EQ(info.backend, "osmesa");
    EXPECT_GE(info.major * 10 + info.minor, 45) << info.version;
    GLint profile = 0;
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
    EXPECT_TRUE(profile & GL_CONTEXT_CORE_PROFILE_BIT);
}

TEST(GlContext, EGLGives45Core) {
    auto context = gl::createContext(gl::Backend::EGL);
    const auto& info = context->info();
    EXPECT_EQ(info.backend, "egl");
    EXPECT_GE(info.major * 10 + info.minor, 45) << info.version;
    // A compute dispatch works (the GI pipeline is made of them).
    EXPECT_NE(glDispatchCompute, nullptr);
}

TEST(GlContext, UnknownBackendNamesTheChoices) {
    try {
        gl::parseBackend("vulkan");
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("osmesa"), std::string::npos);
    }
}

TEST(Shader, IncludesExpandOnceWithLineDirectives) {
    const auto dir = test::testDir();
    std::ofstream(dir / "main.comp") << "#version 450\n#include \"a.glsl\"\n#include \"a.glsl\"\nvoid main() {}\n";
    std::ofstream(dir / "a.glsl") << "// a\nconst float A = 1.0;\n";
    setenv("VCT_SHADER_DIR", dir.c_str(), 1);
    const auto source = gl::preprocessShader("main.comp", {"FOO 1"});
    unsetenv("VCT_SHADER_DIR");
    ASSERT_EQ(source.files.size(), 2u);
    EXPECT_EQ(source.files[1], "a.glsl");
    // #version first, then the shader interface's names, then the caller's define, and exactly
    // one copy of a.glsl.
    EXPECT_EQ(source.text.rfind("#version 450\n#define ", 0), 0u) << source.text;
    const auto interfaceName = source.text.find("#define SSBO_NODE_CHILD " + std::to_string(gl::SSBO_NODE_CHILD) + "\n");
    const auto define = source.text.find("#define FOO 1\n");
    EXPECT_NE(interfaceName, std::string::npos);
    EXPECT_NE(define, std::string::npos);
    EXPECT_LT(interfaceName, define);
    const auto first = source.text.find("const float A");
    EXPECT_NE(first, std::string::npos);
    EXPECT_EQ(source.text.find("const float A", first + 1), std::string::npos);
    EXPECT_NE(source.text.find("#line 1 1\n"), std::string::npos);
}

TEST(Shader, BindingsNamedInTheShaderInterfaceAreTheOnesCppBinds) {
    // A shader that declares its buffer and image by the interface's names; the linked program
    // reports the binding points C++ uses.
    const auto dir = test::testDir();
    std::ofstream(dir / "bindings.comp")
        << "#version 450\nlayout(local_size_x = 1) in;\n"
           "layout(std430, binding = SSBO_CELL_AREA) buffer CellArea { float cellArea[]; };\n"
           "layout(binding = TEXTURE_OPACITY_PLUS) uniform sampler3D uOpacity;\n"
           "void main() { cellArea[0] = texture(uOpacity, vec3(0.5)).x; }\n";
    auto context = gl::createContext(gl::defaultBackend());
    setenv("VCT_SHADER_DIR", dir.c_str(), 1);
    const gl::Program program = gl::buildProgram({{GL_COMPUTE_SHADER, "bindings.comp"}});
    unsetenv("VCT_SHADER_DIR");
    const GLuint block = glGetProgramResourceIndex(program.id(), GL_SHADER_STORAGE_BLOCK, "CellArea");
    const GLenum property = GL_BUFFER_BINDING;
    GLint binding = -1;
    glGetProgramResourceiv(program.id(), GL_SHADER_STORAGE_BLOCK, block, 1, &property, 1, nullptr, &binding);
    EXPECT_EQ(binding, GLint(gl::SSBO_CELL_AREA));
    GLint unit = -1;
    glGetUniformiv(program.id(), glGetUniformLocation(program.id(), "uOpacity"), &unit);
    EXPECT_EQ(unit, GLint(gl::TEXTURE_OPACITY_PLUS));
}

TEST(Shader, CompileErrorNamesFileAndLine) {
    const auto dir = test::testDir();
    std::ofstream(dir / "bad.comp") << "#version 450\nlayout(local_size_x = 1) in;\n#include \"broken.glsl\"\n"
                                       "void main() {}\n";
    std::ofstream(dir / "broken.glsl") << "// line 1\n// line 2\nfloat f() { return undefined_symbol; }\n";
    auto context = gl::createContext(gl::defaultBackend());
    setenv("VCT_SHADER_DIR", dir.c_str(), 1);
    std::string message;
    try {
        gl::buildProgram({{GL_COMPUTE_SHADER, "bad.comp"}});
    } catch (const Error& e) {
        message = e.what();
    }
    unsetenv("VCT_SHADER_DIR");
    EXPECT_NE(message.find("broken.glsl:3"), std::string::npos) << message;
    EXPECT_NE(message.find("undefined_symbol"), std::string::npos) << message;
}

TEST(Shader, MapsNvidiaStyleLogs) {
    const std::string mapped = gl::mapShaderLog("1(7) : error C1008: undefined variable \"x\"\n", {"main.comp", "inc.glsl"});
    EXPECT_EQ(mapped.rfind("inc.glsl:7:", 0), 0u) << mapped;
}
