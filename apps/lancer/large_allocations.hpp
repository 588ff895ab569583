// How the CLI's memory is set up before anything is allocated (large_allocations.cpp).
#pragma once

namespace lancer::cli {

// The small allocations on transparent huge pages too: glibc's malloc reads its settings
// (GLIBC_TUNABLES: glibc.malloc.hugetlb=1, a 64 MiB top pad) only when the process starts, so the
// first call runs the program again with them, once, at the start of main (the variable is then
// put back as it was, so that programs lancer starts see the user's). Nothing changes when the
// user's GLIBC_TUNABLES already chooses glibc.malloc.hugetlb, when transparent huge pages are off,
// or when the program cannot be run again. Returns only when no new run took over.
void tuneMallocForHugePages(char** argv);

}  // namespace lancer::cli
