#include "gl/shader.hpp"

#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>

#include <glm/gtc/type_ptr.hpp>

#include "core/error.hpp"
#include "gl/shader_interface.hpp"

namespace vct::gl {
namespace fs = std::filesystem;

fs::path shaderDirectory() {
    if (const char* env = std::getenv("VCT_SHADER_DIR"); env && *env) return env;
    return VCT_SHADER_DIR;
}

namespace {

std::string readShaderFile(const std::string& file) {
    const fs::path path = shaderDirectory() / file;
    std::ifstream in(path);
    if (!in) fail("shader '", path.string(), "' not found; set VCT_SHADER_DIR to the vct shaders/ folder");
    std::stringstream content;
    content << in.rdbuf();
    return content.str();
}

// gl/shader_interface.hpp as #define lines, the same for every shader.
const std::string& shaderInterfaceDefines() {
    static const std::string text = [] {
        std::string lines;
#define VCT_SHADER_INTERFACE_DEFINE(name, value) lines += concat("#define ", #name, " ", value, "\n");
        VCT_SHADER_INTERFACE(VCT_SHADER_INTERFACE_DEFINE)
#undef VCT_SHADER_INTERFACE_DEFINE
        return lines;
    }();
    return text;
}

const std::regex kInclude(R"(^\s*#\s*include\s+"([^"]+)\"\s*$)");
const std::regex kVersion(R"(^\s*#\s*version\b.*$)");

void expand(const std::string& file, PreprocessedSource& out, std::vector<std::string>& stack, bool isMain,
            const std::vector<std::string>& defines) {
    for (const auto& open : stack)
        if (open == file) fail("shader include cycle: '", file, "' includes itself");
    for (const auto& seen : out.files)
        if (seen == file) return;  // each file once (#pragma once semantics)
    const int index = int(out.files.size());
    out.files.push_back(file);
    stack.push_back(file);
    std::istringstream lines(readShaderFile(file));
    std::string line;
    int number = 0;
    bool versionSeen = !isMain;
    if (!isMain) out.text += concat("#line 1 ", index, "\n");
    while (std::getline(lines, line)) {
        ++number;
        std::smatch match;
        if (std::regex_match(line, kVersion)) {
            if (!isMain) fail("shader '", file, "' line ", number, ": #version belongs only in the main file");
            out.text += line + "\n";
            out.text += shaderInterfaceDefines();
            for (const auto& define : defines) out.text += "#define " + define + "\n";
            out.text += concat("#line ", number + 1, " ", index, "\n");
            versionSeen = true;
        } else if (std::regex_match(line, match, kInclude)) {
            if (!versionSeen) fail("shader '", file, "' line ", number, ": #include before #version");
            expand(match[1].str(), out, stack, false, defines);
            out.text += concat("#line ", number + 1, " ", index, "\n");
        } else {
            out.text += line + "\n";
        }
    }
    if (isMain && !versionSeen) fail("shader '", file, "' has no #version line (vct shaders use #version 450)");
    stack.pop_back();
}

std::string shaderInfoLog(GLuint shader) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::string log(std::size_t(std::max(length, 1)), '\0');
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    return log.c_str();
}

std::string programInfoLog(GLuint program) {
    GLint length = 0;
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    std::string log(std::size_t(std::max(length, 1)), '\0');
    glGetProgramInfoLog(program, length, nullptr, log.data());
    return log.c_str();
}

}  // namespace

PreprocessedSource preprocessShader(const std::string& file, const std::vector<std::string>& defines) {
    PreprocessedSource out;
    std::vector<std::string> stack;
    expand(file, out, stack, true, defines);
    return out;
}

std::string mapShaderLog(const std::string& log, const std::vector<std::string>& files) {
    static const std::regex mesa(R"((\d+):(\d+)\((\d+)\))");   // 0:12(5)
    static const std::regex nvidia(R"((\d+)\((\d+)\)\s*:)");  // 0(12) :
    std::string result;
    std::istringstream lines(log);
    std::string line;
    auto fileName = [&](const std::string& index) {
        const std::size_t i = std::stoul(index);
        return i < files.size() ? files[i] : "source " + index;
    };
    while (std::getline(lines, line)) {
        std::smatch m;
        if (std::regex_search(line, m, mesa) && m.position(0) == 0)
            line = fileName(m[1]) + ":" + m[2].str() + ":" + m[3].str() + m.suffix().str();
        else if (std::regex_search(line, m, nvidia) && m.position(0) == 0)
            line = fileName(m[1]) + ":" + m[2].str() + ":" + m.suffix().str();  // the match ate the colon
        result += line + "\n";
    }
    return result;
}

Program buildProgram(const std::vector<ShaderStage>& stages, const std::vector<std::string>& defines) {
    Program program(glCreateProgram());
    std::vector<Shader> shaders;
    std::string names;
    for (const auto& stage : stages) {
        names += (names.empty() ? "" : " + ") + stage.file;
        const PreprocessedSource source = preprocessShader(stage.file, defines);
        Shader shader(glCreateShader(stage.type));
        const char* text = source.text.c_str();
        glShaderSource(shader.id(), 1, &text, nullptr);
        glCompileShader(shader.id());
        GLint ok = 0;
        glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
        if (!ok)
            fail("shader '", stage.file, "' failed to compile:\n", mapShaderLog(shaderInfoLog(shader.id()), source.files));
        glAttachShader(program.id(), shader.id());
        shaders.push_back(std::move(shader));
    }
    glLinkProgram(program.id());
    GLint ok = 0;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
    if (!ok) fail("shader program '", names, "' failed to link:\n", programInfoLog(program.id()));
    for (const auto& shader : shaders) glDetachShader(program.id(), shader.id());
    const std::string label = names;
    glObjectLabel(GL_PROGRAM, program.id(), GLsizei(label.size()), label.c_str());
    return program;
}

void setUniform(GLuint p, const char* n, int v) { glProgramUniform1i(p, glGetUniformLocation(p, n), v); }
void setUniform(GLuint p, const char* n, unsigned v) { glProgramUniform1ui(p, glGetUniformLocation(p, n), v); }
void setUniform(GLuint p, const char* n, float v) { glProgramUniform1f(p, glGetUniformLocation(p, n), v); }
void setUniform(GLuint p, const char* n, const glm::vec2& v) {
    glProgramUniform2fv(p, glGetUniformLocation(p, n), 1, glm::value_ptr(v));
}
void setUniform(GLuint p, const char* n, const glm::vec3& v) {
    glProgramUniform3fv(p, glGetUniformLocation(p, n), 1, glm::value_ptr(v));
}
void setUniform(GLuint p, const char* n, const glm::vec4& v) {
    glProgramUniform4fv(p, glGetUniformLocation(p, n), 1, glm::value_ptr(v));
}
void setUniform(GLuint p, const char* n, const glm::ivec2& v) {
    glProgramUniform2iv(p, glGetUniformLocation(p, n), 1, glm::value_ptr(v));
}
void setUniform(GLuint p, const char* n, const glm::ivec3& v) {
    glProgramUniform3iv(p, glGetUniformLocation(p, n), 1, glm::value_ptr(v));
}
void setUniform(GLuint p, const char* n, const glm::mat3& v) {
    glProgramUniformMatrix3fv(p, glGetUniformLocation(p, n), 1, GL_FALSE, glm::value_ptr(v));
}
void setUniform(GLuint p, const char* n, const glm::mat4& v) {
    glProgramUniformMatrix4fv(p, glGetUniformLocation(p, n), 1, GL_FALSE, glm::value_ptr(v));
}

}  // namespace vct::gl
