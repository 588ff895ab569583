// A prefetch the compiler keeps. GCC 12 deletes a __builtin_prefetch (and _mm_prefetch) that follows
// a test doing only loads, since the prefetch is no side effect to it; an asm statement is one. Used
// where a loop chases addresses far apart (the kd build's partition, the .pos reader's point table).
#pragma once

namespace lancer {

inline void prefetchLine(const void* at) {
#if defined(__x86_64__) || defined(__i386__)
  asm volatile("prefetcht0 %0" : : "m"(*static_cast<const char*>(at)));
#else
  __builtin_prefetch(at);
#endif
}

}  // namespace lancer
