/* Stands in for Embree on a GPU machine that has too little room to carry it (benchmarks/gpu_bundle.sh):
   vct render never traces a ray on the CPU; the reference path tracer and its tests do, and fail
   cleanly with "Embree could not create a device", because no device can be made. Every other
   entry point the binaries import only exists to satisfy the loader and is never reached. */
#include <stddef.h>

void* rtcNewDevice(const char* config) { (void)config; return NULL; }
int rtcGetDeviceError(void* device) { (void)device; return 1; /* RTC_ERROR_UNKNOWN */ }

#define UNREACHABLE(name) void* name(void) { return NULL; }
UNREACHABLE(rtcAttachGeometry)
UNREACHABLE(rtcCommitGeometry)
UNREACHABLE(rtcCommitScene)
UNREACHABLE(rtcGetDeviceProperty)
UNREACHABLE(rtcIntersect1)
UNREACHABLE(rtcNewGeometry)
UNREACHABLE(rtcNewScene)
UNREACHABLE(rtcOccluded1)
UNREACHABLE(rtcReleaseDevice)
UNREACHABLE(rtcReleaseGeometry)
UNREACHABLE(rtcReleaseScene)
UNREACHABLE(rtcSetDeviceErrorFunction)
UNREACHABLE(rtcSetGeometryIntersectFilterFunction)
UNREACHABLE(rtcSetGeometryOccludedFilterFunction)
UNREACHABLE(rtcSetGeometryUserData)
UNREACHABLE(rtcSetSceneBuildQuality)
UNREACHABLE(rtcSetSceneFlags)
UNREACHABLE(rtcSetSharedGeometryBuffer)
