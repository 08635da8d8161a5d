#pragma once
// The fixed-function state a raster pass draws with, set as a whole when the pass begins, so
// that no pass depends on what the previous one left behind.
#include "gl/gl.hpp"

namespace vct::gl {

struct RasterState {
    GLuint framebuffer = 0;
    int width = 0, height = 0;  // the viewport
    bool depthTest = false;     // with depth writes; GL_GREATER: reversed depth (render/view.hpp)
};

// Binds the framebuffer and sets the viewport and depth test as asked; every surface is
// two-sided (no culling), and nothing blends, scissors or masks colour writes.
inline void beginRasterPass(const RasterState& state) {
    glBindFramebuffer(GL_FRAMEBUFFER, state.framebuffer);
    glViewport(0, 0, state.width, state.height);
    if (state.depthTest) {
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_GREATER);
        glDepthMask(GL_TRUE);
    } else {
        glDisable(GL_DEPTH_TEST);
    }
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

// Returns to the default framebuffer (the window, for the viewer).
inline void endRasterPass() { glBindFramebuffer(GL_FRAMEBUFFER, 0); }

}  // namespace vct::gl
