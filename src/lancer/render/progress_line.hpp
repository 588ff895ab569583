// The one-line progress of a render on stderr (percent, speed, time left), redrawn in place: what
// `lancer render` and lancer.render(progress=True) show.
#pragma once

#include "lancer/render/renderer.hpp"

namespace lancer {

void printProgressLine(const RenderProgress& progress);

}  // namespace lancer
