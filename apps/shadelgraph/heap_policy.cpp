#include "heap_policy.hpp"

#include <cstdlib>  // defines __GLIBC__ where it is glibc

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace sg::app {

void keepFreedHeapMemory() {
#if defined(__GLIBC__)
  // Setting either threshold also stops glibc adjusting them at run time.
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 64 << 20);
#endif
}

}  // namespace sg::app
