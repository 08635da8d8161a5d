#pragma once
// The one include for OpenGL in vct: the glad 2 loader generated at configure time (gl:core=4.5).
#include <glad/gl.h>

#include <string>

namespace vct::gl {

// Throws vct::Error if GL reported an error since the last check. Out-of-memory gets its own
// message (the user can lower resolution or voxel levels); anything else is an engine bug and
// says so. `what` names the operation, e.g. "allocating the G-buffer".
void checkErrors(const std::string& what);

const char* errorName(GLenum error);

}  // namespace vct::gl
