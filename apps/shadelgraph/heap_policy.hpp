#pragma once
// How the process's heap hands memory back to the kernel. A frame loop frees
// and allocates again about the same memory every frame (a render graph of
// 1000 passes and its plan: about 1 MB); glibc's default gives the top of the
// heap back as soon as 128 KiB or more are free there, so every frame faults
// the same pages in again (measured: 1000 passes declared and compiled with a
// new graph took 4.4 ms instead of 0.7 ms, 250 page faults each, issue 14).

namespace sg::app {

// Keeps up to 64 MiB of freed heap for the next allocations and serves
// allocations up to 32 MiB from the heap, where glibc's own adjustment would
// end up after the first large free (a 4 MiB bound made every texture upload
// map and fault its pages: DamagedHelmet's render 97 k -> 122 k faults; this
// way 82 k, 5% more peak memory). No-op outside glibc.
void keepFreedHeapMemory();

}  // namespace sg::app
