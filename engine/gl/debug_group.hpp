#pragma once
// A KHR_debug group for the lifetime of the object: GL debuggers (RenderDoc, apitrace) show the
// commands inside it under `name`, so a frame reads as the pass table.
#include <string>

#include "gl/gl.hpp"

namespace vct::gl {

class DebugGroup {
public:
    explicit DebugGroup(const std::string& name) {
        glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, GLsizei(name.size()), name.c_str());
    }
    ~DebugGroup() { glPopDebugGroup(); }
    DebugGroup(const DebugGroup&) = delete;
    DebugGroup& operator=(const DebugGroup&) = delete;
};

}  // namespace vct::gl
