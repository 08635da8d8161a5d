#pragma once
// Checks a model file before Assimp reads it, for malformations that Debian 12's Assimp 5.2
// does not survive on its own: it allocates what a header declares before reading it, and it
// writes through a null material when an MTL file names a texture before any `newmtl`. Each
// finding is a vct::Error naming the file and what is wrong; a well-formed file passes untouched.
#include <filesystem>

namespace vct {

void precheckModelFile(const std::filesystem::path& path);

}  // namespace vct
