/* Stands in for Mesa's libOSMesa on a GPU machine that renders through EGL only
   (benchmarks/gpu_bundle.sh): the binaries link OSMesa, which drags in all of LLVM, but the EGL
   backend never calls it. Every call fails, so a test that asks for OSMesa reports that the
   backend could not create a context. */
#include <stddef.h>

typedef void* OSMesaContext;

OSMesaContext OSMesaCreateContextAttribs(const int* attributes, OSMesaContext share) {
    (void)attributes;
    (void)share;
    return NULL;
}
void OSMesaDestroyContext(OSMesaContext context) { (void)context; }
unsigned char OSMesaMakeCurrent(OSMesaContext context, void* buffer, unsigned type, int width, int height) {
    (void)context;
    (void)buffer;
    (void)type;
    (void)width;
    (void)height;
    return 0;
}
void* OSMesaGetProcAddress(const char* name) {
    (void)name;
    return NULL;
}
