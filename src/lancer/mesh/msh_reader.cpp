#include "lancer/mesh/msh_reader.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <bit>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <stdexcept>

#include "lancer/mesh/msh_fields.hpp"
#include "lancer/mesh/msh_sections.hpp"

namespace lancer {
namespace {

static_assert(std::endian::native == std::endian::little, "binary .msh reading assumes a little-endian host");

// A read-only private mapping of a whole file, unmapped on destruction.
class MappedFile {
 public:
  explicit MappedFile(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0)
      throw InputError(SourceLocation{path}, fmt::format("cannot open the file: {}", std::strerror(errno)));
    struct stat info {};
    if (::fstat(fd, &info) != 0) {
      const int error = errno;
      ::close(fd);
      throw InputError(SourceLocation{path}, fmt::format("cannot read the file: {}", std::strerror(error)));
    }
    if (S_ISDIR(info.st_mode)) {
      ::close(fd);
      throw InputError(SourceLocation{path}, "is a directory, not a .msh file");
    }
    if (!S_ISREG(info.st_mode)) {
      ::close(fd);
      throw InputError(SourceLocation{path}, "is not a regular file; lancer memory-maps .msh files");
    }
    size_ = static_cast<std::size_t>(info.st_size);
    if (size_ > 0) {
      // No MAP_POPULATE: mapping every page up front measured slower (bench/msh_load_bench.cpp) than
      // letting the sequential parse fault pages in, with the kernel's fault-around.
      void* data = ::mmap(nullptr, size_, PROT_READ, MAP_PRIVATE, fd, 0);
      if (data == MAP_FAILED) {
        const int error = errno;
        ::close(fd);
        throw InputError(SourceLocation{path}, fmt::format("cannot map the file: {}", std::strerror(error)));
      }
      data_ = static_cast<const char*>(data);
    }
    ::close(fd);
  }
  ~MappedFile() {
    if (data_) ::munmap(const_cast<char*>(data_), size_);
  }
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;

  std::span<const char> bytes() const { return {data_, size_}; }

 private:
  const char* data_ = nullptr;
  std::size_t size_ = 0;
};

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

// False when it stopped at a $ElementData because faces did not remember their elements.
bool readSections(MshReadState& state) {
  MshCursor& cursor = state.cursor;
  readMeshFormat(state);
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
    if (name == "$MeshFormat") cursor.failAt(start, "a second $MeshFormat section (two files concatenated?)");
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
      readMshNodeData(state, start);
    } else if (name == "$ElementData") {
      if (state.elementsRead && !state.assembler.tracksElements()) return false;
      readMshElementData(state, start);
    } else {
      // $Comments, $Periodic, $ElementData, $GhostElements, $Parametrizations, ...
      skipSection(cursor, name, start);
    }
  }
  if (!state.nodesRead || !state.elementsRead)
    cursor.failFile(state.nodesRead ? "the file has $Nodes but no $Elements section (truncated?)"
                                    : "the file has no $Nodes and $Elements sections: it holds no mesh "
                                      "(mesh it in gmsh with -2 or -3 before saving)");
  return true;
}

Mesh readBytes(std::span<const char> bytes, const std::string& name, std::uint64_t fileBytes) {
  // Faces remember their element (8 bytes each) only when a $ElementData needs it. gmsh writes it
  // after $Elements, so the first read does not track, and meeting one reads the file again with
  // tracking: twice the load time for those files only, and no cost (not even a scan) for others.
  for (const bool track : {false, true}) {
    MshCursor cursor(bytes, name);
    if (bytes.empty()) cursor.failFile("the file is empty");
    MshMeshAssembler assembler;
    if (track) assembler.trackElements();
    MeshSourceInfo source;
    source.path = name;
    source.fileBytes = fileBytes;
    MshReadState state(cursor, assembler, source);
    if (readSections(state)) return assembler.finish(std::move(source), std::move(state.namedGroups));
  }
  throw std::logic_error("readBytes: the tracking read stopped at $ElementData");
}

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

Mesh readMshFromMemory(std::span<const char> bytes, const std::string& nameForErrors) {
  const auto start = std::chrono::steady_clock::now();
  Mesh mesh = readBytes(bytes, nameForErrors, bytes.size());
  mesh.source.loadSeconds = secondsSince(start);
  return mesh;
}

Mesh readMsh(const std::string& path) {
  const auto start = std::chrono::steady_clock::now();
  const MappedFile file(path);
  Mesh mesh = readBytes(file.bytes(), path, file.bytes().size());
  mesh.source.loadSeconds = secondsSince(start);
  return mesh;
}

}  // namespace lancer
