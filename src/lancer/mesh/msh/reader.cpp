#include "lancer/mesh/msh_reader.hpp"

#include <fmt/format.h>
#include <sys/mman.h>

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <stdexcept>

#include "lancer/mesh/field_steps.hpp"
#include "lancer/mesh/msh/fields.hpp"
#include "lancer/mesh/msh/foreign_formats.hpp"
#include "lancer/mesh/msh/mesh_assembler.hpp"
#include "lancer/mesh/msh/sections.hpp"
#include "lancer/mesh/msh/stored_steps.hpp"
#include "lancer/mesh/pos/pos_file_kind.hpp"
#include "lancer/mesh/pos/pos_mesh.hpp"
#include "lancer/mesh/pos/pos_on_mesh.hpp"
#include "lancer/util/input_error.hpp"
#include "lancer/util/mapped_file.hpp"
#include "lancer/util/stopwatch.hpp"

namespace lancer {
namespace {

static_assert(std::endian::native == std::endian::little, "binary .msh reading assumes a little-endian host");

void readMeshFormat(MshReadState& state) {
  MshCursor& cursor = state.cursor;
  const char* start = cursor.tokenStart();
  const std::string_view first = cursor.token();
  if (first != "$MeshFormat") {
    if (first == "$NOD" || first == "$NOE")
      cursor.failAt(start, "this is an MSH 1 file; lancer reads MSH 2.2, 4.0 and 4.1 (re-save it with gmsh)");
    cursor.failAt(start, "not a gmsh mesh: a .msh file starts with $MeshFormat");
  }
  const char* versionAt = cursor.tokenStart();
  const std::string version(cursor.token());
  if (version == "4.1") {
    state.major = 4, state.minor = 1;
  } else if (version == "4" || version == "4.0") {
    state.major = 4, state.minor = 0;
  } else if (version.size() >= 1 && version[0] == '2' && (version.size() == 1 || version[1] == '.')) {
    state.major = 2, state.minor = 2;
  } else {
    cursor.failAt(versionAt,
                  fmt::format("MSH version '{}' is not supported; lancer reads MSH 2.2, 4.0 and 4.1 "
                              "(gmsh -format msh41 writes 4.1)",
                              version.substr(0, 16)));
  }
  state.source.formatVersion = state.major == 2 ? version : (state.minor == 1 ? "4.1" : "4.0");
  const char* typeAt = cursor.tokenStart();
  const int fileType = cursor.readInt32("the file type in $MeshFormat");
  if (fileType != 0 && fileType != 1)
    cursor.failAt(typeAt,
                  fmt::format("file type {} in $MeshFormat: expected 0 (ASCII) or 1 (binary)", fileType));
  state.binary = fileType == 1;
  if (state.binary && state.major == 4 && state.minor == 0)
    cursor.failAt(typeAt,
                  "binary MSH 4.0 is not supported (gmsh 4.8 and later no longer write it); re-save the "
                  "mesh as MSH 4.1 with 'gmsh FILE -save -format msh41'");
  state.source.binary = state.binary;
  const char* sizeAt = cursor.tokenStart();
  const int dataSize = cursor.readInt32("the data size in $MeshFormat");
  if (dataSize != 8)
    cursor.failAt(sizeAt, fmt::format("data size {} in $MeshFormat: lancer reads files with 8-byte sizes and "
                                      "doubles (written by 64-bit gmsh)",
                                      dataSize));
  if (state.binary) {
    // The binary check word follows the header line: the int 1 in the writer's byte order.
    cursor.skipLine();
    cursor.setBinaryLocations(true);
    const char* wordAt = cursor.position();
    const auto one = cursor.readRaw<std::int32_t>("the endianness check word in $MeshFormat");
    if (one == 0x01000000)
      cursor.failAt(wordAt,
                    "the binary data is byte-swapped (written on a big-endian machine); lancer reads "
                    "little-endian binary files: re-save it as ASCII with 'gmsh FILE -save -format msh41 "
                    "-bin 0' or on a little-endian machine");
    if (one != 1)
      cursor.failAt(
          wordAt,
          fmt::format("the endianness check word in $MeshFormat is {}, expected 1 (corrupt header)", one));
  }
  cursor.expectToken("$EndMeshFormat", "after the $MeshFormat header");
}

void readPhysicalNames(MshReadState& state) {
  MshCursor& cursor = state.cursor;
  const std::uint64_t count = cursor.readCount("the number of physical names");
  cursor.requireBytes(count, 4 * kMinTextNumberBytes, "$PhysicalNames");
  state.namedGroups.reserve(count);
  for (std::uint64_t i = 0; i < count; ++i) {
    PhysicalGroup group;
    group.dimension = cursor.readInt32("the dimension of a physical group");
    group.tag = cursor.readInt32("the tag of a physical group");
    const char* quote = cursor.tokenStart();
    if (cursor.atEnd() || *quote != '"')
      cursor.failAt(quote, "expected the physical group's name in double quotes");
    const char* nameStart = quote + 1;
    const char* nameEnd = nameStart;
    const char* limit = quote + 1 + std::min<std::uint64_t>(cursor.remaining() - 1, 4096);
    while (nameEnd < limit && *nameEnd != '"' && *nameEnd != '\n') ++nameEnd;
    if (nameEnd == limit || *nameEnd != '"')
      cursor.failAt(quote, "the physical group's name has no closing quote");
    group.name.assign(nameStart, nameEnd);
    cursor.seek(nameEnd + 1);
    state.namedGroups.push_back(std::move(group));
  }
  cursor.expectToken("$EndPhysicalNames", "after the physical names");
}

void skipSection(MshCursor& cursor, std::string_view name, const char* start) {
  const std::string end = fmt::format("$End{}", name.substr(1));
  const void* found = ::memmem(cursor.position(), cursor.remaining(), end.data(), end.size());
  if (!found)
    cursor.failAt(start,
                  fmt::format("section {} has no {} (the file looks truncated)", name.substr(0, 40), end));
  cursor.seek(static_cast<const char*>(found) + end.size());
}

bool isMeshSection(std::string_view name) {
  return name == "$PhysicalNames" || name == "$Entities" || name == "$PartitionedEntities" ||
         name == "$Nodes" || name == "$Elements" || name == "$Periodic" || name == "$GhostElements";
}

// gmsh's view.write(..., append=True) and Save View with PostProcessing.SaveMesh write the mesh
// again before each view: a section the file already had is accepted when it is the same bytes.
void skipRepeatedMeshSection(MshReadState& state, std::string_view name, const char* start) {
  const std::string_view first = state.meshSections.find(name)->second;
  MshCursor& cursor = state.cursor;
  if (static_cast<std::uint64_t>(cursor.remaining() + name.size()) < first.size() ||
      std::memcmp(start, first.data(), first.size()) != 0)
    cursor.failAt(start, fmt::format("a second {} section that differs from the first: lancer reads one mesh "
                                     "per file (gmsh repeats a mesh only before appended views, unchanged)",
                                     name.substr(0, 40)));
  cursor.seek(start + first.size());
}

// The view's name in a field section's header (its first string tag), or "" when it has none.
std::string_view sectionFieldName(const char* from, const char* to) {
  const std::string_view header(from, static_cast<std::size_t>(to - from));
  const std::size_t open = header.find('"');
  if (open == std::string_view::npos || header.find_first_not_of(" \t\r\n0123456789") < open) return {};
  const std::size_t close = header.find_first_of("\"\n", open + 1);
  if (close == std::string_view::npos || header[close] != '"') return {};
  return header.substr(open + 1, std::min<std::size_t>(close - open - 1, 200));
}

// A post-processing section lancer cannot read does not stop the mesh from loading: it is skipped
// to its end marker with a warning (and color_by naming it says why it is missing).
template <typename ReadSection>
void readFieldSection(MshReadState& state, std::string_view name, const char* start, ReadSection read) {
  MshCursor& cursor = state.cursor;
  try {
    read(state, start);
  } catch (const InputError& error) {
    // The end marker: the first line starting with $End after the section's name, as gmsh finds it.
    const char* fileEnd = cursor.position() + cursor.remaining();
    const char* from = start + name.size();
    const void* found = ::memmem(from, static_cast<std::size_t>(fileEnd - from), "\n$End", 5);
    const char* end = found ? static_cast<const char*>(found) + 1 : fileEnd;
    const std::string_view fieldName = sectionFieldName(from, std::min(end, from + 4096));
    const std::string message =
        fmt::format("{}{} skipped: {}", name.substr(0, 40),
                    fieldName.empty() ? "" : fmt::format(" \"{}\"", fieldName), error.message());
    state.source.warnings.push_back(formatInputWarning(error.location(), message));
    state.source.skippedFields.emplace_back(std::string(fieldName), state.source.warnings.back());
    cursor.seek(end);
    cursor.token();  // the $End... marker
  }
}

// Hands back the whole pages of the file mapping within [from, to) to the kernel (see below).
void releasePages(const char* fromAddress, const char* toAddress) {
  const auto page = static_cast<std::uintptr_t>(::sysconf(_SC_PAGESIZE));
  const auto from = (reinterpret_cast<std::uintptr_t>(fromAddress) + page - 1) / page * page;
  const auto to = reinterpret_cast<std::uintptr_t>(toAddress) / page * page;
  if (to > from) ::madvise(reinterpret_cast<void*>(from), to - from, MADV_DONTNEED);
}

// False when it stopped at a $ElementData or $ElementNodeData because faces did not remember their
// elements.
// Hands back the whole pages of the file mapping between state.releaseFrom and the cursor (the
// steps just parsed into floats): MADV_DONTNEED on a private read-only file mapping drops them, and
// any later read of them faults them in from the file again.
void releaseReadPages(MshReadState& state) {
  if (!state.releaseFrom) return;
  releasePages(state.releaseFrom, state.cursor.position());
  const auto page = static_cast<std::uintptr_t>(::sysconf(_SC_PAGESIZE));
  state.releaseFrom =
      reinterpret_cast<const char*>(reinterpret_cast<std::uintptr_t>(state.cursor.position()) / page * page);
}

bool readSections(MshReadState& state) {
  MshCursor& cursor = state.cursor;
  const char* formatStart = cursor.tokenStart();
  readMeshFormat(state);
  state.meshSections.emplace("$MeshFormat", std::string_view(formatStart, cursor.position()));
  for (;;) {
    cursor.skipWhitespace();
    if (cursor.atEnd()) break;
    const char* start = cursor.position();
    const std::string_view name = cursor.token();
    if (name[0] != '$')
      cursor.failAt(start, fmt::format("expected a section such as $Nodes or $Elements, found '{}'",
                                       std::string(name.substr(0, 32))));
    if (name.starts_with("$End"))
      cursor.failAt(start, fmt::format("{} closes a section that was never opened", name.substr(0, 40)));
    if (state.meshSections.count(name)) {
      skipRepeatedMeshSection(state, name, start);
      continue;
    }
    const bool meshSection = isMeshSection(name);
    if (name == "$PhysicalNames") {
      readPhysicalNames(state);
    } else if (name == "$Entities" && state.major == 4) {
      readMsh4Entities(state, false);
    } else if (name == "$PartitionedEntities" && state.major == 4) {
      readMsh4Entities(state, true);
    } else if (name == "$Nodes") {
      if (state.nodesRead) cursor.failAt(start, "a second $Nodes section; lancer reads one per file");
      state.major == 2 ? readMsh2Nodes(state) : readMsh4Nodes(state);
      finishNodes(state, start);
      state.nodesRead = true;
    } else if (name == "$Elements") {
      if (!state.nodesRead)
        cursor.failAt(start, "$Elements comes before $Nodes; elements need their nodes first");
      if (state.elementsRead) cursor.failAt(start, "a second $Elements section; lancer reads one per file");
      state.major == 2 ? readMsh2Elements(state) : readMsh4Elements(state);
      state.elementsRead = true;
    } else if (name == "$NodeData") {
      readFieldSection(state, name, start, readMshNodeData);
      releaseReadPages(state);
    } else if (name == "$ElementData" || name == "$ElementNodeData") {
      if (state.elementsRead && !state.assembler.tracksElements()) return false;
      readFieldSection(state, name, start,
                       name == "$ElementData" ? readMshElementData : readMshElementNodeData);
      releaseReadPages(state);
    } else {
      // Every other section is skipped to its end marker: $Comments, $Periodic, $GhostElements,
      // $Parametrizations, $InterpolationScheme and any unknown one; `lancer info` names them.
      skipSection(cursor, name, start);
      ++state.source.skippedSections[std::string(name.substr(0, 40))];
    }
    if (meshSection)
      state.meshSections.emplace(std::string(name), std::string_view(start, cursor.position()));
  }
  // No $Nodes and no $Elements is an empty mesh (gmsh writes only $Entities for a model whose
  // physical groups have no elements in the dimension meshed); render refuses it with the reason
  // (nothingToDrawReason), info describes it.
  if (state.nodesRead && !state.elementsRead)
    cursor.failFile("the file has $Nodes but no $Elements section (truncated?)");
  return true;
}

// The groups the file declares but no face carries first: further groups of entities in several
// (MSH 4 $Entities, MSH 2 element copies) and groups of entities without elements (a model of
// Physical Volumes meshed in 2D), listed unnamed when $PhysicalNames has no entry for them.
void addDeclaredGroups(MshReadState& state, Mesh& mesh) {
  std::set<std::pair<int, std::int32_t>> known;
  for (const PhysicalGroup& group : mesh.physicalGroups) known.insert({group.dimension, group.tag});
  const auto declare = [&](int dimension, std::int32_t tag) {
    if (dimension >= 2 && tag != 0 && known.insert({dimension, tag}).second)
      mesh.physicalGroups.push_back({dimension, tag, ""});
  };
  for (const auto* entities : {&state.entities, &state.partitionedEntities}) {
    for (const auto& [key, entity] : *entities) {
      const int dimension = static_cast<int>(key >> 32);
      declare(dimension, entity.physical);
      for (const std::int32_t more : entity.morePhysicals) declare(dimension, more);
    }
  }
  for (const ExtraPhysicalGroups& extra : state.extraGroups)
    for (const std::int32_t more : extra.more) declare(extra.dimension, more);
  std::sort(mesh.physicalGroups.begin(), mesh.physicalGroups.end(),
            [](const PhysicalGroup& a, const PhysicalGroup& b) {
              return a.dimension != b.dimension ? a.dimension < b.dimension : a.tag < b.tag;
            });
  mesh.extraPhysicalGroups = std::move(state.extraGroups);
}

// Where the bytes come from: a file (its steps can be left in it) or memory the caller owns.
struct ByteSource {
  std::uint64_t fileBytes = 0;
  bool mapped = false;               // a file mapping: its pages can be handed back
  std::optional<FileIdentity> file;  // set when stored steps can be read again from `name`
  std::uint64_t residentFieldBytes = UINT64_MAX;
  bool keepVolume = false;
};

// Reads the field sections the pass noted, in file order (node data first, as gmsh lists views),
// into mesh.fields after the assembler's own. A section whose records do not parse is skipped with
// a warning, like one whose header does not. When the steps together would take more than
// residentFieldBytes, every step is stored: read here once (checked, its ranges kept) and read
// again when a picture needs it.
void readFieldSections(MshReadState& state, Mesh& mesh, std::span<const char> bytes, const std::string& name,
                       const ByteSource& source) {
  std::vector<MshFieldSection>& sections = state.fieldSections;
  if (sections.empty()) return;
  std::shared_ptr<MshFieldMapping> mapping = state.assembler.takeFieldMapping();
  mapping->minElementTag = state.minElementTag;
  mapping->maxElementTag = state.maxElementTag;
  // Node data first, then element and element-node data, each in file order.
  std::stable_partition(sections.begin(), sections.end(),
                        [](const MshFieldSection& section) { return section.field.at == FieldAt::kNode; });
  const auto items = [&](const MshFieldSection& section) {
    switch (section.field.at) {
      case FieldAt::kNode:
        return mesh.positions.size();
      case FieldAt::kElement:
        return mesh.faces.size();
      case FieldAt::kCorner:
        break;
    }
    return mesh.faces.size() * kCornerSlots;
  };
  std::uint64_t total = 0;
  for (const MshFieldSection& section : sections)
    total += items(section) * static_cast<std::uint64_t>(section.field.components) * sizeof(float);
  std::shared_ptr<const StoredFieldSteps> stored;
  if (source.file && total > source.residentFieldBytes)
    // The absolute path: a Python script may change its folder between reading and rendering.
    stored = std::make_shared<const StoredFieldSteps>(std::filesystem::absolute(name).string(), *source.file,
                                                      mapping, sections);
  MshCursor cursor(bytes, name);
  cursor.setBinaryLocations(state.binary);
  for (std::size_t i = 0; i < sections.size(); ++i) {
    const MshFieldSection& section = sections[i];
    const char* records = bytes.data() + section.recordsBegin;
    cursor.seek(records);
    std::optional<MeshField> field;
    try {
      field = readMshFieldRecords(cursor, section, *mapping, mesh.source.warnings);
    } catch (const InputError& error) {
      const std::string message = fmt::format("{} \"{}\" skipped: {}", mshSectionName(section.field.at),
                                              section.field.name, error.message());
      mesh.source.warnings.push_back(formatInputWarning(error.location(), message));
      mesh.source.skippedFields.emplace_back(section.field.name, mesh.source.warnings.back());
    }
    if (source.mapped) releasePages(records, bytes.data() + section.recordsEnd);
    if (!field) continue;
    field->ranges = componentRanges(field->values, field->components);
    if (stored) {
      auto values = std::make_shared<StoredFieldValues>();
      values->file = stored;
      values->section = i;
      values->items = items(section);
      field->values = std::vector<float>();  // frees it (`= {}` keeps the capacity)
      field->stored = std::move(values);
    }
    mesh.fields.push_back(std::move(*field));
  }
}

// The volume the assembler kept, with the values the field sections gave it; null when none was asked.
std::shared_ptr<const VolumeMesh> takeVolume(MshMeshAssembler& assembler) {
  const std::shared_ptr<MshVolumeCapture> capture = assembler.volumeCapture();
  return capture ? capture->take() : nullptr;
}

// A list-based view: its content says so, or its .pos name when it looks like no mesh either (the
// .pos reader then says what it found instead of a view).
bool isViewContent(std::span<const char> bytes, const std::string& name) {
  if (looksLikeMsh(bytes)) return false;
  if (looksLikePosFile(bytes)) return true;
  std::string extension = std::filesystem::path(name).extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension == ".pos";
}

// Whether the file's last section is $ElementData or $ElementNodeData: its last "$End" marker, read
// from the end (a constant cost, whatever the file's size).
bool endsWithElementData(std::span<const char> bytes) {
  const std::size_t tail = std::min<std::size_t>(bytes.size(), 64);
  const std::string_view end(bytes.data() + bytes.size() - tail, tail);
  const std::size_t marker = end.rfind("$End");
  if (marker == std::string_view::npos) return false;
  const std::string_view name = end.substr(marker);
  return name.starts_with("$EndElementData") || name.starts_with("$EndElementNodeData");
}

Mesh readBytes(std::span<const char> bytes, const std::string& name, const ByteSource& byteSource,
               int threads, std::shared_ptr<const VolumeMesh>* volume = nullptr) {
  if (isViewContent(bytes, name)) {
    MeshSourceInfo source;
    source.path = name;
    source.format = "pos";
    source.fileBytes = byteSource.fileBytes;
    const PosFile pos = readPosFromMemory(bytes, name, threads);
    Mesh mesh = meshFromPos(pos, std::move(source), threads);
    mesh.source.warnings.insert(mesh.source.warnings.begin(), pos.warnings.begin(), pos.warnings.end());
    return mesh;
  }
  // Faces remember their element (16 bytes each) only when a $ElementData or $ElementNodeData needs
  // it. gmsh writes them after $Elements: a file whose last section is one (a solver's result, GetDP's
  // -v2 output, views gmsh appended) tracks from the start; any other reads untracked, and meeting
  // one reads the file again with tracking (twice the load time, for files whose element data
  // comes before their last section only).
  const bool trackFirst = endsWithElementData(bytes);
  for (const bool track : {trackFirst, true}) {
    MshCursor cursor(bytes, name);
    if (bytes.empty()) cursor.failFile("the file is empty");
    if (!looksLikeMsh(bytes)) {
      const std::string foreign =
          foreignFileMessage(bytes.first(std::min<std::size_t>(bytes.size(), 1 << 20)), name);
      if (!foreign.empty()) cursor.failFile(foreign);
    }
    MshMeshAssembler assembler;
    assembler.setThreads(threads);
    if (track) assembler.trackElements();
    if (volume) assembler.keepVolume();
    MeshSourceInfo source;
    source.path = name;
    source.fileBytes = byteSource.fileBytes;
    MshReadState state(cursor, assembler, source);
    if (byteSource.mapped) state.releaseFrom = bytes.data();
    if (readSections(state)) {
      if (!state.fieldSections.empty()) assembler.keepFieldMapping();
      Mesh mesh = assembler.finish(std::move(source), std::move(state.namedGroups));
      readFieldSections(state, mesh, bytes, name, byteSource);
      addDeclaredGroups(state, mesh);
      if (volume) *volume = takeVolume(assembler);
      return mesh;
    }
  }
  throw std::logic_error("readBytes: the tracking read stopped at element data");
}

}  // namespace

Mesh readMshFromMemory(std::span<const char> bytes, const std::string& nameForErrors, int threads) {
  const Stopwatch stopwatch;
  Mesh mesh =
      readBytes(bytes, nameForErrors, ByteSource{bytes.size(), false, std::nullopt, UINT64_MAX}, threads);
  mesh.source.loadSeconds = stopwatch.seconds();
  return mesh;
}

std::uint64_t defaultResidentFieldBytes() {
  const char* text = std::getenv("LANCER_STEP_MEMORY_MB");
  if (!text) return kDefaultResidentFieldBytes;
  std::uint64_t megabytes = 0;
  const char* end = text + std::strlen(text);
  const auto [next, error] = std::from_chars(text, end, megabytes);
  if (error != std::errc() || next != end || *text == '\0' || megabytes > (UINT64_MAX >> 20))
    throw InputError(SourceLocation{"LANCER_STEP_MEMORY_MB"},
                     fmt::format("'{}' is not a number of megabytes; set it to how much memory result steps "
                                 "may take before lancer reads them from their file when needed (e.g. 256)",
                                 text));
  return megabytes << 20;
}

Mesh readMsh(const std::string& path, int threads) {
  return readMsh(path, threads, defaultResidentFieldBytes());
}

Mesh readMsh(const std::string& path, int threads, std::uint64_t residentFieldBytes) {
  const Stopwatch stopwatch;
  const MappedFile file(path, ".msh file");
  const FileIdentity identity{file.bytes().size(), file.modifiedSeconds(), file.modifiedNanoseconds()};
  ByteSource source{file.bytes().size(), true, identity, residentFieldBytes};
  Mesh mesh = readBytes(file.bytes(), path, source, threads);
  mesh.source.loadSeconds = stopwatch.seconds();
  return mesh;
}

MeshWithVolume readMshWithVolume(const std::string& path, int threads) {
  const Stopwatch stopwatch;
  const MappedFile file(path, ".msh file");
  MeshWithVolume result;
  // Every step stays in memory: the volume's values are read with the surface's, once.
  const ByteSource source{file.bytes().size(), true, std::nullopt, UINT64_MAX};
  result.mesh = readBytes(file.bytes(), path, source, threads, &result.volume);
  if (!result.volume) result.volume = std::make_shared<const VolumeMesh>();
  result.mesh.source.loadSeconds = stopwatch.seconds();
  return result;
}

bool isViewFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::vector<char> head(4096);
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(std::max<std::streamsize>(in.gcount(), 0)));
  return isViewContent(head, path);
}

void addViewFiles(Mesh& mesh, const std::vector<std::string>& paths) {
  const Stopwatch stopwatch;
  for (const std::string& path : paths) {
    const PosFile pos = readPosFile(path);
    mesh.source.warnings.insert(mesh.source.warnings.end(), pos.warnings.begin(), pos.warnings.end());
    addPosViews(mesh, pos);
  }
  mesh.source.loadSeconds += stopwatch.seconds();
}

}  // namespace lancer
