// What gmsh's GUI saved about its post-processing views (View[i].* in part.msh.opt, "File > Save
// Model Options"), where lancer means the same: the time step shown, the displacement of a vector
// view drawn as a deformed shape (VectorType = 5, DisplacementFactor) and coloured by another view
// (ExternalView), a vector view drawn as arrows (VectorType 1-4), the range (RangeType, CustomMin,
// CustomMax), iso-values or bands (IntervalsType, NbIso), the colour scale (ShowScale), the colour
// map (ColormapNumber, ColormapSwap) and which views are shown (Visible). View i is the i-th view of
// the mesh file, in file order.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "lancer/mesh/mesh.hpp"
#include "lancer/scene/scene_description.hpp"

namespace lancer {

// gmsh's defaults where the file says nothing (gmsh saves only what changed).
struct GmshPostView {
  int index = 0;                        // View[index]
  std::optional<std::string> name;      // View[i].Name, when saved
  std::optional<int> timeStep;          // View[i].TimeStep: index into the view's steps
  int vectorType = 4;                   // View[i].VectorType: 1-4 arrows, 5 a displacement
  int externalView = -1;                // View[i].ExternalView: the view that colours it (-1: itself)
  double displacementFactor = 1;        // View[i].DisplacementFactor
  int rangeType = 1;                    // 1 default, 2 custom, 3 per time step
  double customMin = 0, customMax = 0;  // gmsh leaves a value out when it is 0
  int intervalsType = 2;                // 1 iso-values, 2 continuous, 3 discrete bands, 4 numeric
  int nbIso = 10;
  bool showScale = true;
  int colormapNumber = 2;     // View[i].ColormapNumber: gmsh's map 0 to 24 (2, its default: jet)
  bool colormapSwap = false;  // View[i].ColormapSwap: the map reversed
  bool visible = true;
  std::int64_t line = 0;               // the first line that sets an option of this view, for messages
  std::vector<std::string> unapplied;  // the options set that lancer does not draw ("Axes", ...)
};

// The View[i] options of a gmsh options file, by view index; empty when it sets none. Throws
// InputError (file:line) for a view option whose value is not a number where one is expected.
std::vector<GmshPostView> readGmshPostViews(const std::string& path);

// Applies the views' options to the description's first mesh (whose file holds the views): the
// displacement view becomes its warp, coloured by its ExternalView (shown or hidden) when it names
// one, else by the first other visible view that is not drawn as arrows (else the displacement's
// magnitude; a hidden view colours nothing), with the range and step gmsh showed; the first visible
// vector view with VectorType 1-4 becomes arrows (coloured by magnitude, as gmsh draws it); the
// options it does not apply are named in one line of description.notes;
// IntervalsType 1 (iso-values) adds isolines of the coloured field at gmsh's NbIso values (both ends
// of the range included), 3 (discrete) NbIso colour bands, 2 (continuous) and 4 the plain map;
// ShowScale puts the legend along the bottom, as gmsh draws its scale, or leaves it out; the view's
// colours are gmsh's map "gmsh:N" (ColormapNumber, reversed with ColormapSwap). A mesh's own color_by
// (its map too), isolines, bands and legend win, as do explicit --step and --warp. Throws InputError at
// the options file for a view index past the mesh's views, a step past the view's last or a
// ColormapNumber gmsh does not have.
void applyGmshPostViews(SceneDescription& description, const Mesh& mesh,
                        const std::vector<GmshPostView>& views, const std::string& path);

}  // namespace lancer
