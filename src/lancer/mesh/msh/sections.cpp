#include "lancer/mesh/msh/sections.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace lancer {

void finishNodes(MshReadState& state, const char* sectionStart) {
  if (state.assembler.nodes.size() >= kNoVertex)
    state.cursor.failAt(sectionStart, fmt::format("{} nodes: lancer reads at most {} per file",
                                                  state.assembler.nodes.size(), kNoVertex - 1));
  state.source.nodeCount = state.assembler.nodes.size();
  if (const auto duplicate = state.assembler.nodes.buildLookup())
    state.cursor.failAt(sectionStart, fmt::format("node tag {} is defined twice in $Nodes", *duplicate));
}

void checkFinite(const MshReadState& state, const Vec3d& p, std::uint64_t tag, const char* at) {
  if (isFinite(p)) return;
  state.cursor.failAt(at,
                      fmt::format("node {} has a non-finite coordinate ({}, {}, {})", tag, p.x, p.y, p.z));
}

void failMissingNode(const MshReadState& state, const char* at, std::uint64_t elementTag, int type,
                     std::uint64_t nodeTag) {
  state.cursor.failAt(at, fmt::format("element {} ({}) uses node {}, which $Nodes does not define",
                                      elementTag, mshElementTypeName(type), nodeTag));
}

void MshReadState::addExtraGroup(int dimension, std::int32_t entity, std::int32_t first, std::int32_t more) {
  if (more == first || more == 0) return;
  auto found = std::find_if(extraGroups.begin(), extraGroups.end(), [&](const ExtraPhysicalGroups& e) {
    return e.dimension == dimension && e.entity == entity && e.first == first;
  });
  if (found == extraGroups.end()) {
    extraGroups.push_back({dimension, entity, first, {}});
    found = extraGroups.end() - 1;
  }
  if (std::find(found->more.begin(), found->more.end(), more) == found->more.end())
    found->more.push_back(more);
}

void MshReadState::warnAt(const char* at, const std::string& message) {
  source.warnings.push_back(formatInputWarning(cursor.locate(at), message));
}

MshElementType requireKnownType(const MshReadState& state, int type, const char* at) {
  const MshElementType info = mshElementType(type);
  if (info.nodeCount == 0)
    state.cursor.failAt(at, fmt::format("element type {} is {}; lancer cannot read its node list", type,
                                        type >= 1 && type <= kMaxMshElementType ? "a variable-size type"
                                                                                : "not a gmsh element type"));
  return info;
}

}  // namespace lancer
