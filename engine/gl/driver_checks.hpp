#pragma once
// Switches that make driver-dependent bugs show on any driver. llvmpipe finishes every dispatch
// before the next starts and hands out zeroed memory, so a pass that asks for too few barrier bits
// or reads storage nobody wrote works there and fails on a GPU. Three environment variables:
//   VCT_GL_ALL_BARRIERS=1  every memory barrier the engine issues covers every kind of access: an
//                          image that changes with it names a pass that asks for too few bits.
//   VCT_GL_FINISH=1        every memory barrier is followed by glFinish, so that no two dispatches
//                          overlap, as on llvmpipe: an image that changes with it on a GPU names an
//                          ordering no barrier bit covers (or a dispatch that issues none).
//   VCT_GL_POISON=1        new buffers start filled with 0x7F bytes (float 3.4e38, uint 2.1e9),
//                          new textures with 3e38 (infinity in half floats, 1 in 8-bit
//                          formats), 0x7F7F7F7F or depth 0.5, instead of what the driver happens
//                          to give: a pass that reads what nobody wrote shows it on llvmpipe too.
#include "gl/gl.hpp"

namespace vct::gl {

// glMemoryBarrier(barriers), or every bit under VCT_GL_ALL_BARRIERS; then glFinish under VCT_GL_FINISH.
void memoryBarrier(GLbitfield barriers);

// Whether VCT_GL_POISON asks new buffers to be filled with the poison byte.
bool poisonNewStorage();
inline constexpr unsigned char kPoisonByte = 0x7F;

// Under VCT_GL_POISON, fills every level of a texture just allocated with storage of
// `internalFormat` with the poison value of its kind; otherwise does nothing.
void poisonNewTexture(GLuint texture, GLenum internalFormat, int levels);

// Whether the current context renders on the CPU (Mesa's llvmpipe or softpipe, SwiftShader), from
// GL_RENDERER: passes whose best layout differs between a CPU and a GPU ask.
bool cpuRasterizer();

}  // namespace vct::gl
