#pragma once
// Loading GLSL programs from shaders/. Sources may `#include "file.glsl"` (resolved relative to
// the shader folder, each file at most once). Errors name the file and line where they occurred
// — not the line in the concatenated source — followed by the driver's log.
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gl/objects.hpp"

namespace vct::gl {

struct ShaderStage {
    GLenum type;       // GL_VERTEX_SHADER, GL_COMPUTE_SHADER, …
    std::string file;  // relative to shaderDirectory()
};

// $VCT_SHADER_DIR if set, else the source tree's shaders/ folder.
std::filesystem::path shaderDirectory();

// After #version come the shader interface's names (gl/shader_interface.hpp) and then `defines`,
// as "#define NAME VALUE" lines.
Program buildProgram(const std::vector<ShaderStage>& stages, const std::vector<std::string>& defines = {});

// Exposed for tests: the expanded source and the files it came from (index = GLSL source-string
// number used in #line directives and in driver logs).
struct PreprocessedSource {
    std::string text;
    std::vector<std::string> files;
};
PreprocessedSource preprocessShader(const std::string& file, const std::vector<std::string>& defines = {});
// Rewrites "0:12(5): error" (Mesa) and "0(12) : error" (NVIDIA) to "file.glsl:12: error".
std::string mapShaderLog(const std::string& log, const std::vector<std::string>& files);

// Uniform setters by name (glProgramUniform*: no need to bind). Unknown names are ignored, as GL
// does, because the compiler removes unused uniforms.
void setUniform(GLuint program, const char* name, int value);
void setUniform(GLuint program, const char* name, unsigned value);
void setUniform(GLuint program, const char* name, float value);
void setUniform(GLuint program, const char* name, const glm::vec2& value);
void setUniform(GLuint program, const char* name, const glm::vec3& value);
void setUniform(GLuint program, const char* name, const glm::vec4& value);
void setUniform(GLuint program, const char* name, const glm::ivec2& value);
void setUniform(GLuint program, const char* name, const glm::ivec3& value);
void setUniform(GLuint program, const char* name, const glm::mat3& value);
void setUniform(GLuint program, const char* name, const glm::mat4& value);

}  // namespace vct::gl
