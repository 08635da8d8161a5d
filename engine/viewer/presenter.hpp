#pragma once
// Puts the renderer's display image into the window: a framebuffer blit of the output texture
// (already tone-mapped, sRGB-encoded RGBA8) onto the default framebuffer, scaled when the render
// resolution differs from the window's; and reads the window back for screenshots.
#include "core/image.hpp"
#include "gl/objects.hpp"

namespace vct::viewer {

class Presenter {
public:
    Presenter();

    // Blits `texture` (width × height, GL origin bottom-left) over the whole default framebuffer.
    void present(GLuint texture, int width, int height, int windowWidth, int windowHeight);
    // Clears the window (e.g. before the first image or when nothing was rendered).
    static void clear(int windowWidth, int windowHeight);
    // The default framebuffer's back buffer as drawn so far this frame, rows top to bottom.
    static Image8 readWindow(int windowWidth, int windowHeight);

private:
    gl::Framebuffer source_;
};

}  // namespace vct::viewer
