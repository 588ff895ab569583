#include "info_accel.hpp"

#include <fmt/format.h>

namespace lancer::cli {

AccelStats buildAccelStats(const Mesh& mesh, AccelKind kind) {
  return Accelerator::build(mesh.positions, mesh.faces, kind).stats();
}

std::string accelStatsText(const AccelStats& s) {
  std::string out =
      fmt::format("accelerator:     {} over {} triangles ({} faces)\n", s.kind, s.triangles, s.faces);
  out += fmt::format("  nodes:         {} ({} leaves, {} empty)\n", s.nodes, s.leaves, s.emptyLeaves);
  out += fmt::format("  depth:         {}\n", s.depth);
  out += fmt::format("  faces/leaf:    {:.2f} mean over non-empty leaves ({} references)\n",
                     s.meanTrianglesPerLeaf, s.triangleReferences);
  out += fmt::format("  SAH cost:      {:.2f}\n", s.sahCost);
  out += fmt::format("  build time:    {:.3f} ms ({:.2f} M triangles/s)\n", s.buildSeconds * 1e3,
                     s.buildMillionTrianglesPerSecond());
  out += fmt::format("  memory:        {} bytes ({:.1f} bytes/triangle)\n", s.bytes, s.bytesPerTriangle());
  return out;
}

std::string accelStatsJson(const AccelStats& s) {
  return fmt::format(
      "  \"accel\": {{\"kind\": \"{}\", \"faces\": {}, \"triangles\": {}, \"nodes\": {}, \"leaves\": {}, "
      "\"emptyLeaves\": {}, \"depth\": {}, \"triangleReferences\": {}, \"meanFacesPerLeaf\": {:.6g}, "
      "\"sahCost\": {:.6g}, \"buildSeconds\": {:.6f}, \"bytes\": {}, \"bytesPerTriangle\": {:.6g}}}",
      s.kind, s.faces, s.triangles, s.nodes, s.leaves, s.emptyLeaves, s.depth, s.triangleReferences,
      s.meanTrianglesPerLeaf, s.sahCost, s.buildSeconds, s.bytes, s.bytesPerTriangle());
}

}  // namespace lancer::cli
