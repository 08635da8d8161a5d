#include "viewer/presenter.hpp"

#include <algorithm>

namespace vct::viewer {

Presenter::Presenter() : source_(gl::createFramebuffer("viewer present source")) {}

void Presenter::present(GLuint texture, int width, int height, int windowWidth, int windowHeight) {
    // The output texture is re-created when the renderer is resized, so attach it every frame.
    glNamedFramebufferTexture(source_.id(), GL_COLOR_ATTACHMENT0, texture, 0);
    glNamedFramebufferReadBuffer(source_.id(), GL_COLOR_ATTACHMENT0);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_FRAMEBUFFER_SRGB);  // the texture is sRGB-encoded already: copy the bytes
    const bool sameSize = width == windowWidth && height == windowHeight;
    if (!sameSize) clear(windowWidth, windowHeight);
    glBlitNamedFramebuffer(source_.id(), 0, 0, 0, width, height, 0, 0, windowWidth, windowHeight, GL_COLOR_BUFFER_BIT,
                           sameSize ? GL_NEAREST : GL_LINEAR);
    glNamedFramebufferTexture(source_.id(), GL_COLOR_ATTACHMENT0, 0, 0);
}

void Presenter::clear(int windowWidth, int windowHeight) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, windowWidth, windowHeight);
    glDisable(GL_SCISSOR_TEST);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
}

Image8 Presenter::readWindow(int windowWidth, int windowHeight) {
    Image8 image(windowWidth, windowHeight);
    std::vector<std::uint8_t> rows(image.rgba.size());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    glReadPixels(0, 0, windowWidth, windowHeight, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
    const std::size_t rowBytes = std::size_t(windowWidth) * 4;
    for (int y = 0; y < windowHeight; ++y)  // GL rows are bottom to top
        std::copy_n(&rows[std::size_t(windowHeight - 1 - y) * rowBytes], rowBytes, image.at(0, y));
    for (std::size_t i = 3; i < image.rgba.size(); i += 4) image.rgba[i] = 255;  // the window's alpha is not an image's
    return image;
}

}  // namespace vct::viewer
