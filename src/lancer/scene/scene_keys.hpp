// The keys a scene file may hold, table by table: the one list the loader's readers check a file
// against (TomlTableReader rejects any other key, with a suggestion), and that docs/scene_file.md
// lists too (tests/scene/scene_file_doc_test.cpp fails when the two differ).
#pragma once

#include <span>
#include <string_view>

namespace lancer {

// Every table of a scene file that a TomlTableReader reads. A new table gets a value here and its
// keys in scene_keys.cpp; a new key goes into its table's list there (and a row in the manual).
enum class SceneTable {
  Document,  // the top level: the names of the tables below
  Render,
  Camera,
  Ambient,
  Light,
  Material,
  Mesh,
  MeshEdges,
  MeshColorBy,
  MeshIsolines,
  MeshArrows,
  MeshClip,
  Clip,
  Floor,
  Animation,
  MeshWarp,
  Environment,
  MeshSlice,
  MeshIsosurfaces,
  MeshStreamlines,
};

struct SceneTableKeys {
  SceneTable table;
  // How docs/scene_file.md heads the table's section: "render", "light", "material.NAME",
  // "mesh.edges", ...; "" for the document's top level.
  std::string_view header;
  std::span<const std::string_view> keys;  // in the order messages list them
};

// The keys of one table, in the order messages list them.
std::span<const std::string_view> sceneKeys(SceneTable table);

// Every table with its keys, in the order of SceneTable.
std::span<const SceneTableKeys> sceneFileKeys();

}  // namespace lancer
