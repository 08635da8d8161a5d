// OSMesa backend: an offscreen 4.5 core context on Mesa's llvmpipe. Rendering goes to
// engine-owned FBOs; OSMesa's own colour buffer is a 1×1 placeholder that nothing draws to.
#include <GL/osmesa.h>

#include <array>

#include "core/error.hpp"
#include "gl/context.hpp"

namespace vct::gl {
namespace {

class OSMesaContextImpl final : public Context {
public:
    explicit OSMesaContextImpl(const ContextOptions& options) {
        const std::array<int, 13> attributes = {
            OSMESA_FORMAT,                OSMESA_RGBA,
            OSMESA_DEPTH_BITS,            24,
            OSMESA_PROFILE,               OSMESA_CORE_PROFILE,
            OSMESA_CONTEXT_MAJOR_VERSION, 4,
            OSMESA_CONTEXT_MINOR_VERSION, 5,
            0, 0, 0};
        context_ = OSMesaCreateContextAttribs(attributes.data(), nullptr);
        if (!context_)
            fail("the osmesa backend could not create an OpenGL 4.5 core context (Mesa too old or built "
                 "without llvmpipe?); install libosmesa6 from Debian 12 or later, or try --backend egl");
        makeCurrent();
        initialize("osmesa", [](const char* name) { return reinterpret_cast<void*>(OSMesaGetProcAddress(name)); },
                   options);
    }
    ~OSMesaContextImpl() override { OSMesaDestroyContext(context_); }

    void makeCurrent() override {
        if (!OSMesaMakeCurrent(context_, placeholder_.data(), GL_UNSIGNED_BYTE, 1, 1))
            fail("the osmesa backend could not make its context current");
    }

private:
    OSMesaContext context_ = nullptr;
    std::array<unsigned char, 4> placeholder_{};
};

}  // namespace

std::unique_ptr<Context> createOSMesaContext(const ContextOptions& options) {
    return std::make_unique<OSMesaContextImpl>(options);
}

}  // namespace vct::gl
