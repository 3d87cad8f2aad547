#pragma once
// How the process's heap hands memory back to the kernel. A frame loop frees
// and allocates again about the same memory every frame (a render graph of
// 1000 passes and its plan: about 1 MB); glibc's default gives the top of the
// heap back as soon as 128 KiB or more are free there, so every frame faults
// the same pages in again (measured: 1000 passes declared and compiled with a
// new graph took 4.4 ms instead of 0.7 ms, 250 page faults each, issue 14).

namespace sg::app {

// Keeps up to 64 MiB of freed heap for the next allocations and serves
// allocations up to 4 MiB from the heap (larger ones, decoded images and
// meshes, are still mapped and given back on free). No-op outside glibc.
void keepFreedHeapMemory();

}  // namespace sg::app
