// `lancer info FILE.msh --accel [KIND]`: builds the acceleration structure over the mesh and
// describes it (shape of the tree, SAH cost, build time and memory), as text or a JSON member.
#pragma once

#include <string>

#include "lancer/accel/accelerator.hpp"
#include "lancer/mesh/mesh.hpp"

namespace lancer::cli {

AccelStats buildAccelStats(const Mesh& mesh, AccelKind kind);
std::string accelStatsText(const AccelStats& stats);
// `"accel": {...}`, without a trailing comma, for the info command's JSON object.
std::string accelStatsJson(const AccelStats& stats);

}  // namespace lancer::cli
