// The scene keys of results over time: a [[mesh]]'s `warp = { field, factor }` and `undeformed`,
// `[render] step`, and `[animation] over = "steps"`, `range`, `label`, `label_position`. Read here,
// beside the loader, so that the loader stays one screen per table.
#pragma once

#include <optional>
#include <string>

#include "lancer/scene/scene_description.hpp"
#include "lancer/scene/toml_table_reader.hpp"

namespace lancer {

// The [[mesh]]'s `warp` and `undeformed` into `mesh`.
void readWarpKeys(const TomlTableReader& reader, MeshInstance& mesh);

// `[animation] over`, `range`, `label`, `label_position` into `animation`.
void readAnimationStepKeys(const TomlTableReader& reader, AnimationSettings& animation);

// "t = {time:.3g} s" with the frame's time and step (fmt's format syntax: {time}, {step}, with a
// format spec after a colon). Throws InputError at `where` for a name other than time and step or a
// spec that does not fit.
std::string formatStepLabel(const std::string& label, double time, int step, const SourceLocation& where);

}  // namespace lancer
