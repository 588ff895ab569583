// lancer.release_memory and the arena's accounting (util/huge_page_blocks.hpp): the module's large
// allocations are kept for the next render of the session, and given back on request.
#include "bindings.hpp"
#include "lancer/util/huge_page_blocks.hpp"

namespace lancer::python {

void bindMemory(py::module_& module) {
  module.def(
      "release_memory",
      [] {
        const std::size_t retained = largeBlockStats().retainedBytes;
        releaseRetainedLargeBlocks();
        return retained;
      },
      "Gives the memory kept for the next render back to the system; returns its bytes.");
  module.def("_memory_stats", [] {
    const LargeBlockStats stats = largeBlockStats();
    py::dict out;
    out["in_use_bytes"] = stats.inUseBytes;
    out["retained_bytes"] = stats.retainedBytes;
    out["peak_mapped_bytes"] = stats.peakMappedBytes;
    out["mapped_blocks"] = stats.mappedBlocks;
    out["reused_blocks"] = stats.reusedBlocks;
    out["unmapped_blocks"] = stats.unmappedBlocks;
    out["moved_blocks"] = stats.movedBlocks;
    return out;
  });
}

}  // namespace lancer::python
