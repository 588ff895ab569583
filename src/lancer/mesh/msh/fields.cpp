#include "lancer/mesh/msh/fields.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "lancer/mesh/msh/element_types.hpp"
#include "lancer/mesh/msh/volume_capture.hpp"
#include "lancer/util/huge_pages.hpp"

namespace lancer {
namespace {

// A field record's node or element tag: a 4-byte int in binary files, a number in text ones.
std::uint64_t readRecordTag(MshCursor& cursor, bool binary, const char* what) {
  return binary ? static_cast<std::uint64_t>(cursor.readRaw<std::int32_t>(what)) : cursor.readCount(what);
}

// Largest component count gmsh writes (a 3x3 tensor).
constexpr int kMaxComponents = 9;

struct FieldHeader {
  std::string name;
  double time = 0;
  int step = 0;
  int components = 1;
  std::uint64_t count = 0;
};

// A double-quoted string tag; gmsh writes one per line.
std::string readQuoted(MshCursor& cursor) {
  const char* quote = cursor.tokenStart();
  if (cursor.atEnd() || *quote != '"') cursor.failAt(quote, "expected a string tag in double quotes");
  const char* nameStart = quote + 1;
  const char* limit = quote + 1 + std::min<std::uint64_t>(cursor.remaining() - 1, 4096);
  const char* nameEnd = nameStart;
  while (nameEnd < limit && *nameEnd != '"' && *nameEnd != '\n') ++nameEnd;
  if (nameEnd == limit || *nameEnd != '"') cursor.failAt(quote, "the string tag has no closing quote");
  cursor.seek(nameEnd + 1);
  return {nameStart, nameEnd};
}

FieldHeader readHeader(MshReadState& state, const char* section) {
  MshCursor& cursor = state.cursor;
  FieldHeader header;
  const char* at = cursor.tokenStart();
  const int stringTags = cursor.readInt32("the number of string tags");
  if (stringTags < 0 || stringTags > 64)
    cursor.failAt(
        at, fmt::format("{} string tags in {}: expected 1 (the view's name) or a few", stringTags, section));
  for (int i = 0; i < stringTags; ++i) {
    std::string tag = readQuoted(cursor);
    if (i == 0) header.name = std::move(tag);
  }
  at = cursor.tokenStart();
  const int realTags = cursor.readInt32("the number of real tags");
  if (realTags < 0 || realTags > 64)
    cursor.failAt(at, fmt::format("{} real tags in {}: expected 1 (the time) or a few", realTags, section));
  for (int i = 0; i < realTags; ++i) {
    const double value = cursor.readDouble("a real tag");
    if (i == 0) header.time = value;
  }
  at = cursor.tokenStart();
  const int integerTags = cursor.readInt32("the number of integer tags");
  if (integerTags < 3 || integerTags > 64)
    cursor.failAt(at, fmt::format("{} integer tags in {}: expected at least 3 (time step, components, count)",
                                  integerTags, section));
  header.step = cursor.readInt32("the time step");
  at = cursor.tokenStart();
  header.components = cursor.readInt32("the number of components");
  if (header.components < 1 || header.components > kMaxComponents)
    cursor.failAt(
        at, fmt::format("{} components in {}: expected 1 to {}", header.components, section, kMaxComponents));
  header.count = cursor.readCount("the number of values");
  for (int i = 3; i < integerTags; ++i) cursor.readInt64("an integer tag");  // partition, ...
  return header;
}

// An element-node record's count of nodes: 1 to the most nodes an element type has.
std::uint64_t readElementNodeCount(MshCursor& cursor, bool binary) {
  const char* at = binary ? cursor.position() : cursor.tokenStart();
  const std::int64_t count = binary ? cursor.readRaw<std::int32_t>("the element's number of nodes")
                                    : cursor.readShortInt64("the element's number of nodes");
  if (count < 1 || count > kMaxMshElementNodes)
    cursor.failAt(at, fmt::format("an element with {} nodes in $ElementNodeData: expected 1 to {} (the "
                                  "number of nodes of the element, then its values)",
                                  count, kMaxMshElementNodes));
  return static_cast<std::uint64_t>(count);
}

// gmsh ends a post-processing section at the first token that starts with $End (its own tutorial
// file view5.msh closes an $ElementData with $EndElememtData, and gmsh reads it), so lancer does too.
void expectFieldSectionEnd(MshCursor& cursor, std::string_view expected, const char* context) {
  MshCursor peek = cursor;
  if (peek.token().starts_with("$End")) {
    cursor.token();
    return;
  }
  cursor.expectToken(expected, context);
}

// Notes where the section's records are and moves the cursor past them to the end marker: binary
// records by their size (their bytes may hold anything), text ones to the first "$End" (a number
// never holds a '$', and gmsh ends the section at the first such token too).
void skipRecords(MshReadState& state, MshFieldSection section, const char* sectionStart, const char* what,
                 std::string_view endMarker) {
  MshCursor& cursor = state.cursor;
  const auto components = static_cast<std::uint64_t>(section.field.components);
  const bool perCorner = section.field.at == FieldAt::kCorner;
  // An element-node record holds a node count and at least one node's values.
  const std::uint64_t recordBytes = state.binary
                                        ? 4 + (perCorner ? 4 : 0) + 8 * components
                                        : (1 + (perCorner ? 1 : 0) + components) * kMinTextNumberBytes;
  if (state.binary) cursor.skipLine();
  cursor.requireBytes(section.count, recordBytes, what);
  section.binary = state.binary;
  section.sectionBegin = cursor.offset() - static_cast<std::uint64_t>(cursor.position() - sectionStart);
  section.recordsBegin = cursor.offset();
  if (state.binary && perCorner) {
    // Records differ in size by their node count: walked, each count checked against the bytes left.
    for (std::uint64_t i = 0; i < section.count; ++i) {
      cursor.readRaw<std::int32_t>("an element tag");
      const std::uint64_t nodes = readElementNodeCount(cursor, true);
      cursor.requireBytes(nodes, 8 * components, what);
      cursor.advance(nodes * 8 * components);
    }
  } else if (state.binary) {
    cursor.advance(section.count * recordBytes);
  } else {
    const void* end = ::memmem(cursor.position(), cursor.remaining(), "$End", 4);
    if (!end)
      cursor.failAt(sectionStart, fmt::format("{} '{}' has no {} (the file looks truncated)", what,
                                              section.field.name, endMarker));
    cursor.seek(static_cast<const char*>(end));
  }
  section.recordsEnd = cursor.offset();
  expectFieldSectionEnd(cursor, endMarker,
                        fmt::format("after the {} data values", fieldAtName(section.field.at)).c_str());
  state.fieldSections.push_back(std::move(section));
}

MshFieldSection sectionOf(FieldHeader header, FieldAt at) {
  MshFieldSection section;
  section.field.name = std::move(header.name);
  section.field.at = at;
  section.field.step = header.step;
  section.field.time = header.time;
  section.field.components = header.components;
  section.count = header.count;
  return section;
}

// One value of a record: finite, else an error at it naming the section, the view and the record.
float readFieldValue(MshCursor& cursor, bool binary, const char* section, const std::string& view,
                     const char* item, std::uint64_t tag) {
  const char* valueAt = binary ? cursor.position() : cursor.tokenStart();
  const double value = binary ? cursor.readRaw<double>("a field value") : cursor.readDouble("a field value");
  if (!std::isfinite(value))
    cursor.failAt(valueAt, fmt::format("{} '{}' has a non-finite value for {} {}", section, view, item, tag));
  return static_cast<float>(value);
}

// The records' values in mesh-vertex order.
void readNodeRecords(MshCursor& cursor, const MshFieldSection& section, const MshFieldMapping& mapping,
                     MeshField& field, std::vector<std::string>& warnings) {
  const bool binary = section.binary;
  const auto components = static_cast<std::uint64_t>(field.components);
  field.values.assign(mapping.nodeCount * components, std::numeric_limits<float>::quiet_NaN());
  // Values for nodes the file does not save (a view built over all of a model's nodes, saved with
  // only its physical groups' elements) are dropped, with one warning for the section.
  std::uint64_t dropped = 0, firstDropped = 0;
  const char* firstDroppedAt = nullptr;
  for (std::uint64_t i = 0; i < section.count; ++i) {
    // Binary records may start with bytes that look like whitespace: only text skips to the token.
    const char* recordAt = binary ? cursor.position() : cursor.tokenStart();
    const std::uint64_t tag = readRecordTag(cursor, binary, "a node tag");
    const std::uint32_t index = mapping.nodes.find(tag);
    if (index == kNoVertex && dropped++ == 0) firstDropped = tag, firstDroppedAt = recordAt;
    float* out = index == kNoVertex ? nullptr : field.values.data() + index * components;
    for (std::uint64_t c = 0; c < components; ++c) {
      const float value = readFieldValue(cursor, binary, "$NodeData", field.name, "node", tag);
      if (out) out[c] = value;
    }
  }
  if (dropped)
    warnings.push_back(formatInputWarning(
        cursor.locate(firstDroppedAt),
        fmt::format("$NodeData '{}' gives values for {} node{} that $Nodes does not define (the "
                    "first: node {}); they were dropped and the other {} kept",
                    field.name, dropped, dropped == 1 ? "" : "s", static_cast<std::int64_t>(firstDropped),
                    section.count - dropped)));
  if (mapping.volume) mapping.volume->addNodeField(field, field.values);
  remapNodeValues(field.values, field.components, mapping.usedNode, mapping.usedCount,
                  mapping.nodes.taggedCount(), mapping.derivedSources);
}

// Records of element data naming a tag outside the file's element tags: dropped, counted, and said
// in one warning naming the first. Tag 0 is gmsh's placeholder for an element it did not save (Save
// View writes one for each point of a model without physical points): dropped without a word, as
// gmsh itself reads it.
struct DroppedElements {
  std::uint64_t count = 0, first = 0;
  const char* firstAt = nullptr;

  void check(std::uint64_t tag, const MshFieldMapping& mapping, const char* recordAt) {
    if (tag != 0 && (tag < mapping.minElementTag || tag > mapping.maxElementTag) && count++ == 0)
      first = tag, firstAt = recordAt;
  }
  void warn(MshCursor& cursor, const char* section, const std::string& view, std::uint64_t records,
            std::vector<std::string>& warnings) const {
    if (count == 0) return;
    warnings.push_back(formatInputWarning(
        cursor.locate(firstAt),
        fmt::format("{} '{}' gives values for {} element{} that $Elements does not hold (the first: element "
                    "{}); they were dropped and the other {} kept",
                    section, view, count, count == 1 ? "" : "s", static_cast<std::int64_t>(first),
                    records - count)));
  }
};

// The records' values per face, from the element each face came from.
void readElementRecords(MshCursor& cursor, const MshFieldSection& section, const MshFieldMapping& mapping,
                        MeshField& field, std::vector<std::string>& warnings) {
  const bool binary = section.binary;
  const auto components = static_cast<std::uint64_t>(field.components);
  // Records naming an element that made no face are ignored: gmsh writes values for every element
  // of a view, lines and points too. Tags outside the file's element tags are dropped with a warning.
  std::vector<float> values;
  std::vector<std::uint64_t> tags;
  values.reserve(section.count * components);
  tags.reserve(section.count);
  DroppedElements dropped;
  for (std::uint64_t i = 0; i < section.count; ++i) {
    const char* recordAt = binary ? cursor.position() : cursor.tokenStart();
    const std::uint64_t tag = readRecordTag(cursor, binary, "an element tag");
    dropped.check(tag, mapping, recordAt);
    tags.push_back(tag);
    for (std::uint64_t c = 0; c < components; ++c)
      values.push_back(readFieldValue(cursor, binary, "$ElementData", field.name, "element", tag));
  }
  dropped.warn(cursor, "$ElementData", field.name, section.count, warnings);
  if (mapping.volume) mapping.volume->addElementField(field, tags, values);
  field.values = mapElementValues(std::move(tags), values, field.components, mapping.faceElement,
                                  mapping.elementAliases, mapping.covered);
}

// The records' values per face corner, from the record of the element each face came from. gmsh
// writes a record per element, tagged 1..N in order, all of one node count: while the records go
// on so, only their values are kept (no tag, offset or count per record: 20 bytes a record written
// and read back), and the records are found by their offset; the first record that breaks the run
// turns on the full tables, filled for the records before it.
void readElementNodeRecords(MshCursor& cursor, const MshFieldSection& section, const MshFieldMapping& mapping,
                            MeshField& field, std::vector<std::string>& warnings) {
  const bool binary = section.binary;
  const auto components = static_cast<std::uint64_t>(field.components);
  ElementNodeRecords records;
  // A guess of three nodes a record (a triangle); the count was checked against the file's bytes.
  records.values.reserve(section.count * components * 3);
  adviseHugePages(records.values);
  std::uint64_t firstTag = 0;
  std::uint32_t runNodes = 0;
  bool run = true;  // every record so far tagged firstTag + its index, with runNodes nodes
  const auto startTables = [&](std::uint64_t recordsSoFar) {
    run = false;
    records.tags.reserve(section.count);
    records.firstValue.reserve(section.count);
    records.nodeCount.reserve(section.count);
    adviseHugePages(records.tags);
    adviseHugePages(records.firstValue);
    adviseHugePages(records.nodeCount);
    for (std::uint64_t r = 0; r < recordsSoFar; ++r) {
      records.tags.push_back(firstTag + r);
      records.firstValue.push_back(r * runNodes * components);
      records.nodeCount.push_back(runNodes);
    }
  };
  DroppedElements dropped;
  for (std::uint64_t i = 0; i < section.count; ++i) {
    const char* recordAt = binary ? cursor.position() : cursor.tokenStart();
    const std::uint64_t tag = readRecordTag(cursor, binary, "an element tag");
    dropped.check(tag, mapping, recordAt);
    const std::uint64_t nodes = readElementNodeCount(cursor, binary);
    cursor.requireBytes(nodes, binary ? 8 * components : components * kMinTextNumberBytes,
                        "the element's node values");
    if (i == 0) firstTag = tag, runNodes = static_cast<std::uint32_t>(nodes);
    if (run && (tag != firstTag + i || nodes != runNodes)) startTables(i);
    if (!run) {
      records.tags.push_back(tag);
      records.firstValue.push_back(records.values.size());
      records.nodeCount.push_back(static_cast<std::uint32_t>(nodes));
    }
    for (std::uint64_t v = 0; v < nodes * components; ++v)
      records.values.push_back(
          readFieldValue(cursor, binary, "$ElementNodeData", field.name, "element", tag));
  }
  dropped.warn(cursor, "$ElementNodeData", field.name, section.count, warnings);
  // Aliases rename tags, and the volume keeps the records as they are: both take the full tables.
  if (run && (!mapping.elementAliases.empty() || mapping.volume)) startTables(section.count);
  if (mapping.volume) mapping.volume->addElementNodeField(field, records);
  if (run && section.count > 0) {
    const UniformElementNodeRecords uniform{firstTag, section.count, runNodes, records.values.data(),
                                            runNodes * components};
    field.values = mapElementNodeValues(uniform, field.components, mapping.faceElement,
                                        mapping.faceCornerNode, mapping.covered);
  } else {
    field.values = mapElementNodeValues(std::move(records), field.components, mapping.faceElement,
                                        mapping.faceCornerNode, mapping.elementAliases, mapping.covered);
  }
}

}  // namespace

void readMshNodeData(MshReadState& state, const char* sectionStart) {
  if (!state.nodesRead)
    state.cursor.failAt(sectionStart, "$NodeData comes before $Nodes; its values need the nodes");
  skipRecords(state, sectionOf(readHeader(state, "$NodeData"), FieldAt::kNode), sectionStart, "$NodeData",
              "$EndNodeData");
}

void readMshElementData(MshReadState& state, const char* sectionStart) {
  if (!state.elementsRead)
    state.cursor.failAt(sectionStart, "$ElementData comes before $Elements; its values need the elements");
  skipRecords(state, sectionOf(readHeader(state, "$ElementData"), FieldAt::kElement), sectionStart,
              "$ElementData", "$EndElementData");
}

void readMshElementNodeData(MshReadState& state, const char* sectionStart) {
  if (!state.elementsRead)
    state.cursor.failAt(sectionStart,
                        "$ElementNodeData comes before $Elements; its values need the elements");
  skipRecords(state, sectionOf(readHeader(state, "$ElementNodeData"), FieldAt::kCorner), sectionStart,
              "$ElementNodeData", "$EndElementNodeData");
}

MeshField readMshFieldRecords(MshCursor& cursor, const MshFieldSection& section,
                              const MshFieldMapping& mapping, std::vector<std::string>& warnings) {
  MeshField field = section.field;
  switch (field.at) {
    case FieldAt::kNode:
      readNodeRecords(cursor, section, mapping, field, warnings);
      break;
    case FieldAt::kElement:
      readElementRecords(cursor, section, mapping, field, warnings);
      break;
    case FieldAt::kCorner:
      readElementNodeRecords(cursor, section, mapping, field, warnings);
      break;
  }
  // A text section with more records than its count: what follows the last one is not its end.
  if (!section.binary && (cursor.skipWhitespace(), cursor.offset() < section.recordsEnd))
    cursor.fail(
        fmt::format("expected $End{} after the {} records the section's count gives, found more values",
                    std::string_view(mshSectionName(field.at)).substr(1), section.count));
  return field;
}

}  // namespace lancer
