// The command line's options for the inside of a volume (docs/volume.md): --slice, --skin,
// --isosurfaces, --isovalues, --streamlines, --seed-line, --seed-rectangle and --streamline-radius,
// as the renderer's overrides.
#pragma once

#include <CLI/CLI.hpp>

#include "lancer/scene/render_overrides.hpp"
#include "scene_setup.hpp"

namespace lancer::cli {

// Registers them on `command`, in the "Inside the volume" group of --help.
void addVolumeOptions(CLI::App& command, SceneOverrides& overrides);

// Turns them into `applied`'s slices, skin, isosurfaces and streamlines; an InputError at the option
// for a value that says nothing it can use.
void applyVolumeOptions(const SceneOverrides& overrides, RenderOverrides& applied);

}  // namespace lancer::cli
