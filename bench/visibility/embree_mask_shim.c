/* embree_mask_shim.c: LD_PRELOAD shim that makes Debian's python3-open3d 0.16 RaycastingScene
 * see triangles (bench/visibility/anchor_open3d.py only; not part of shadetool).
 *
 * Debian builds Embree with ray masks enabled (EMBREE_RAY_MASK), and Open3D 0.16 fills every ray
 * with mask = 0, so every ray misses (DEPENDENCIES.md). The two stream calls Open3D makes,
 * rtcIntersect1M (cast_rays) and rtcOccluded1M (test_occlusions), are wrapped here: each ray's
 * mask is set to all ones, then the real function of libembree3.so.3 is called (looked up in that
 * library's handle: Python loads Open3D's module, and with it Embree, RTLD_LOCAL, where RTLD_NEXT
 * does not reach). Nothing else changes: Open3D still builds its own BVH and traces its own rays, on the
 * same Embree 3.13.5 shadetool uses, so it is not an independent reference of the traversal.
 *
 *   cc -O2 -shared -fPIC embree_mask_shim.c -o embree_mask_shim.so -ldl
 *   LD_PRELOAD=./embree_mask_shim.so python3 anchor_open3d.py ...
 */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <embree3/rtcore.h>

typedef void (*intersect_fn)(RTCScene, struct RTCIntersectContext*, struct RTCRayHit*, unsigned, size_t);
typedef void (*occluded_fn)(RTCScene, struct RTCIntersectContext*, struct RTCRay*, unsigned, size_t);

static void* real_symbol(const char* name) {
  void* embree = dlopen("libembree3.so.3", RTLD_NOW | RTLD_NOLOAD);
  if (!embree) embree = dlopen("libembree3.so.3", RTLD_NOW);
  void* f = embree ? dlsym(embree, name) : NULL;
  if (!f) {
    fprintf(stderr, "embree_mask_shim: %s not found in libembree3.so.3\n", name);
    abort();
  }
  return f;
}

/* The ray is the first member of RTCRayHit, so both calls set the mask at the same offset. */
static void unmask(void* rays, unsigned count, size_t stride) {
  for (unsigned i = 0; i < count; ++i)
    ((struct RTCRay*)((char*)rays + (size_t)i * stride))->mask = 0xFFFFFFFFu;
}

void rtcIntersect1M(RTCScene scene, struct RTCIntersectContext* context, struct RTCRayHit* rays, unsigned int count,
                    size_t byteStride) {
  static intersect_fn real = NULL;
  if (!real) real = (intersect_fn)real_symbol("rtcIntersect1M");
  unmask(rays, count, byteStride);
  real(scene, context, rays, count, byteStride);
}

void rtcOccluded1M(RTCScene scene, struct RTCIntersectContext* context, struct RTCRay* rays, unsigned int count,
                   size_t byteStride) {
  static occluded_fn real = NULL;
  if (!real) real = (occluded_fn)real_symbol("rtcOccluded1M");
  unmask(rays, count, byteStride);
  real(scene, context, rays, count, byteStride);
}
