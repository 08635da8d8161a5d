// Constants shared by the shaders (the C++ side: engine/core/math_constants.hpp).
const float PI = 3.14159265358979323846;
