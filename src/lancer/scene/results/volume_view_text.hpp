// What is drawn inside the volume, written as text, as the command line's --slice, --isosurfaces
// and --streamlines and Python's slices=, isosurfaces= and streamlines= take it (docs/volume.md).
#pragma once

#include <optional>
#include <string>
#include <utility>

#include "lancer/scene/results/volume_view_spec.hpp"
#include "lancer/util/input_error.hpp"

namespace lancer {

// AXIS (x, -y, ...: through the centre of the volume's bounding box), AXIS=VALUE or
// PX,PY,PZ,NX,NY,NZ, as a cutting plane's text; an InputError at `where` (the option) otherwise.
SliceSpec sliceFromText(const std::string& text, const SourceLocation& where);

// FIELD[:COUNT]: the field, and the count when given (a whole number from 1 to `most`); an InputError
// at `option` (its name, "--isosurfaces") otherwise.
std::pair<std::string, std::optional<int>> fieldAndCountFromText(const std::string& text,
                                                                 const std::string& option, int most);

// "2px", "0.5 px": a number of pixels (finite; its sign is the caller's to check); nothing for any
// other text (a plain number is a length in model units).
std::optional<double> pixelsFromText(const std::string& text);

}  // namespace lancer
