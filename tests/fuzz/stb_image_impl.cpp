// stb_image compiled into the fuzzer itself (instead of Debian's prebuilt libstb), so that its
// decoders run with ASan and libFuzzer's coverage instrumentation.
#define STB_IMAGE_IMPLEMENTATION
#include <stb_image.h>
