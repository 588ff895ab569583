#include "lancer/mesh/pos/pos_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cctype>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <thread>

#include "lancer/mesh/pos/pos_file_kind.hpp"
#include "lancer/mesh/pos/pos_scanner.hpp"
#include "lancer/mesh/pos/pos_split.hpp"
#include "lancer/util/huge_pages.hpp"
#include "lancer/util/mapped_file.hpp"
#include "lancer/util/memory_budget.hpp"
#include "lancer/util/thread_count.hpp"

namespace lancer {
namespace {

constexpr int kMaxNodes = 27;  // a second-order hexahedron
constexpr std::size_t kMaxSteps = 1 << 30;

std::string plural(std::size_t count, std::string_view one, std::string_view many) {
  return fmt::format("{} {}", count, count == 1 ? one : many);
}

// A piece of a large file parsed on a thread of its own: the run of elements from `begin` (lines
// counted from 1 there), in a view of their own (blocks in order of first use, one step count), up
// to the first element at or after the next piece's start or the first thing that is no element
// of that run (the end of the view, a TIME list, an error): `stop`, on `stopLine`. The serial parse
// takes the piece when it reaches `begin` inside a view whose step count is the piece's, and reads
// on from `stop` itself; what a piece could not read it reads, and reports, as it would alone.
struct PosPiece {
  const char* begin = nullptr;
  const char* limit = nullptr;
  const char* stop = nullptr;
  std::int64_t stopLine = 1;
  PosView view;
};

class PosParser {
 public:
  PosParser(std::span<const char> bytes, const std::string& name)
      : scan_(bytes, name), limit_(bytes.data() + bytes.size()) {
    result_.file = name;
  }

  // The pieces the parse may take (their threads are waited for, in order, when it reaches them).
  void usePieces(std::span<PosPiece> pieces, std::span<std::thread> threads) {
    pieces_ = pieces;
    threads_ = threads;
  }

  // Reads piece.begin's run of elements, up to piece.limit (see PosPiece); never throws for the
  // file's content: where the run stops, the serial parse reads on. `cancel` stops it early.
  void parsePiece(PosPiece& piece, const std::atomic<bool>& cancel) {
    limit_ = piece.limit;
    scan_.seekTo(piece.begin, 1);
    piece.stop = piece.begin;
    PosView& view = piece.view;
    ViewState state;
    state.blockOfSlot.fill(-1);
    try {
      while (!cancel.load(std::memory_order_relaxed)) {
        scan_.skipSpace();
        const char* at = scan_.position();
        if (at >= limit_) break;
        const std::int64_t line = scan_.line();
        const std::string_view code = scan_.name();
        if (code.empty() || code != state.lastCode) {
          const auto kind = posElementKind(code);
          if (!kind) break;
          state.lastCode = code;
          state.lastKind = *kind;
        }
        readElement(view, state, state.lastKind, at, line);
        piece.stop = scan_.position();
        piece.stopLine = scan_.line();
      }
    } catch (...) {  // the serial parse meets it again and reports it (or runs out of memory) itself
    }
    // An element that failed half-way may have left values (and coordinates) behind.
    for (PosElementBlock& block : view.blocks) {
      const std::size_t elements = block.elementCount();
      block.values.resize(elements * static_cast<std::size_t>(block.kind.nodes * block.kind.components) *
                          static_cast<std::size_t>(view.stepCount));
      block.coords.resize(elements * 3 * static_cast<std::size_t>(block.kind.nodes));
    }
  }

  PosFile parse() {
    refuseOtherFormats(scan_.bytes(), scan_.file());
    for (scan_.skipSpace(); !scan_.atEnd(); scan_.skipSpace()) {
      const char* at = scan_.position();
      if (scan_.name() != "View") {
        scan_.failAt(
            at, fmt::format("expected a view (View \"name\" {{ ... }};) or the end of the file, found {}: "
                            "lancer reads the views of a .pos file, not gmsh commands",
                            describeAt(at)));
      }
      readView(at);
    }
    if (result_.views.empty())
      throw InputError(SourceLocation{result_.file},
                       "the file holds no view: a list-based .pos file holds views like "
                       "View \"name\" { ST(x1,y1,z1,x2,y2,z2,x3,y3,z3){v1,v2,v3}; };");
    return std::move(result_);
  }

 private:
  // What a view being read knows besides what it keeps.
  struct ViewState {
    std::array<int, kPosKindSlots> blockOfSlot;  // index into view.blocks, -1 for none yet
    std::int64_t stepsFrom = 0;                  // line of the TIME list or element that set stepCount
    bool stepsFromTime = false;
    bool stepsKnown = false;
    std::int64_t timeLine = 0;
    const char* firstText = nullptr;
    std::string_view lastCode;  // the code of the last element, and its kind
    PosElementKind lastKind;
    const char* firstElement = nullptr;  // where the view's first element starts
  };

  std::string describeAt(const char* at) {
    PosScanner copy = scan_;
    copy.seekTo(at);
    return copy.describeNext();
  }

  void readView(const char* viewAt) {
    PosView& view = result_.views.emplace_back();
    view.line = scan_.line();
    view.name = scan_.quotedString("after View");
    const std::string context = fmt::format("after View \"{}\"", view.name);
    if (!scan_.accept('{')) scan_.failExpected("'{'", context);
    ViewState state;
    state.blockOfSlot.fill(-1);
    for (;;) {
      const char c = scan_.peek();
      if (nextPiece_ < pieces_.size() && takePiece(view, state)) continue;
      if (c == '}') {
        scan_.accept('}');
        if (!scan_.accept(';'))
          scan_.failExpected("';'", fmt::format("after the closing '}}' of view \"{}\"", view.name));
        break;
      }
      if (c == '\0' && scan_.atEnd())
        scan_.failAt(viewAt,
                     fmt::format("the file ends inside view \"{}\": expected its closing '}};' (the file "
                                 "looks truncated)",
                                 view.name));
      const char* at = scan_.position();
      const std::int64_t line = scan_.line();
      const std::string_view code = scan_.name();
      if (!code.empty() && code == state.lastCode) {  // the common case: a run of elements of one code
        readElement(view, state, state.lastKind, at, line);
      } else if (const auto kind = posElementKind(code)) {
        state.lastCode = code;
        state.lastKind = *kind;
        readElement(view, state, *kind, at, line);
      } else if (code == "TIME") {
        readTime(view, state, at, line);
      } else if (code == "T2" || code == "T3") {
        skipText(code == "T2" ? 3 : 4);
        if (view.skippedTexts++ == 0) state.firstText = at;
      } else {
        refuseItem(view, code, at);
      }
    }
    for (PosElementBlock& block : view.blocks) {
      giveBackUnused(block.coords);
      giveBackUnused(block.values);
      giveBackUnused(block.lines);
    }
    if (state.stepsKnown && !view.timesGiven)
      for (int step = 0; step < view.stepCount; ++step) view.times.push_back(step);
    if (view.skippedTexts > 0)
      result_.warnings.push_back(formatInputWarning(
          scan_.locate(state.firstText),
          fmt::format("skipped {} of view \"{}\": lancer draws no text from a .pos file",
                      plural(view.skippedTexts, "text annotation (T2, T3)", "text annotations (T2, T3)"),
                      view.name)));
  }

  // Appends the piece that starts here, when one does and its elements continue this view (the
  // same step count); then reads on where it stopped. Pieces the parse has passed are not used.
  bool takePiece(PosView& view, ViewState& state) {
    const char* at = scan_.position();
    while (nextPiece_ < pieces_.size() && pieces_[nextPiece_].begin < at) ++nextPiece_;
    if (nextPiece_ == pieces_.size() || pieces_[nextPiece_].begin != at) return false;
    if (threads_[nextPiece_].joinable()) threads_[nextPiece_].join();
    PosPiece& piece = pieces_[nextPiece_++];
    if (piece.stop == piece.begin || !state.stepsKnown || view.blocks.empty() ||
        piece.view.stepCount != view.stepCount)
      return false;
    const std::int64_t lineOffset = scan_.line() - 1;
    for (PosElementBlock& from : piece.view.blocks) {
      if (from.elementCount() == 0) continue;
      PosElementBlock& to = blockFor(view, state, from.kind);
      reserveFor(to.coords, from.coords.size(), at);
      to.coords.insert(to.coords.end(), from.coords.begin(), from.coords.end());
      reserveFor(to.values, from.values.size(), at);
      to.values.insert(to.values.end(), from.values.begin(), from.values.end());
      reserveFor(to.lines, from.lines.size(), at);
      for (const std::int64_t line : from.lines) to.lines.push_back(line + lineOffset);
      from = PosElementBlock{from.kind, {}, {}, {}};  // its memory goes back now
    }
    scan_.seekTo(piece.stop, lineOffset + piece.stopLine);
    return true;
  }

  [[noreturn]] void refuseItem(const PosView& view, std::string_view code, const char* at) {
    if (code == "INTERPOLATION_SCHEME")
      scan_.failAt(
          at, fmt::format("view \"{}\" gives its values as polynomial coefficients (INTERPOLATION_SCHEME), "
                          "which lancer does not read: write the view as values at nodes (GetDP's "
                          "Print[..., OnElementsOf ...] does)",
                          view.name));
    if (code.size() >= 2 && code.size() <= 3 && (code[0] == 'S' || code[0] == 'V' || code[0] == 'T'))
      scan_.failAt(at, fmt::format("unknown element type '{}' in view \"{}\": {}", code, view.name,
                                   posElementCodeHelp()));
    scan_.failAt(
        at, fmt::format("expected an element (ST(...){{...}};), TIME{{...}}; or the closing '}};' of view "
                        "\"{}\", found {}: lancer reads the lists gmsh and GetDP write, not .geo "
                        "commands or expressions",
                        view.name, describeAt(at)));
  }

  // Grows `v` to hold `extra` more items, checking the memory budget first. Every item was read from
  // the file's bytes, so what is allocated stays proportional to the file's size.
  template <typename T>
  void reserveFor(std::vector<T>& v, std::size_t extra, const char* at) {
    if (v.size() + extra <= v.capacity()) return;
    const std::size_t capacity = std::max({v.capacity() * 2, v.size() + extra, std::size_t{1024}});
    const std::uint64_t more = (capacity - v.capacity()) * sizeof(T);
    // The location costs a count of the lines before it: only for the message.
    if (allocated_ + more > memoryBudget())
      requireMemory(allocated_ + more, scan_.locate(at), "the views of this .pos file");
    moveTo(v, capacity);
  }

  // Moves `v` to an array of `capacity` items advised to huge pages before the copy first touches it
  // (4 KiB page faults took a third of the load time otherwise).
  template <typename T>
  void moveTo(std::vector<T>& v, std::size_t capacity) {
    allocated_ += capacity * sizeof(T);
    allocated_ -= v.capacity() * sizeof(T);
    std::vector<T> moved;
    moved.reserve(capacity);
    adviseHugePages(moved);
    moved.insert(moved.end(), v.begin(), v.end());
    v.swap(moved);
  }

  // After the first kSampleElements elements of a view: room for as many more as the rest of the file
  // could hold at their mean size, when the memory budget allows it. Growing by doubling instead
  // copied and cleared twice the memory the view takes; reserved pages cost nothing until they are
  // filled, and what the view leaves unused is given back at its end (giveBackUnused).
  static constexpr std::size_t kSampleElements = 1024;
  void reserveForView(PosElementBlock& block, const ViewState& state, std::size_t valueCount) {
    const std::size_t elementBytes = std::max<std::size_t>(
        1, static_cast<std::size_t>(scan_.position() - state.firstElement) / kSampleElements);
    const auto bytesLeft = static_cast<std::size_t>(std::max(limit_ - scan_.position(), std::ptrdiff_t{0}));
    // A quarter more than the mean says: elements later in the file may print shorter numbers, and
    // outgrowing the reserve copies every value so far to fresh pages.
    const std::size_t elements = block.elementCount() + bytesLeft / elementBytes * 5 / 4 + 1;
    const std::uint64_t bytes =
        saturatingProduct(elements, 3 * block.kind.nodes * sizeof(double) + valueCount * sizeof(float) + 8);
    if (allocated_ + bytes > memoryBudget()) return;  // grow by doubling, checked at each step
    moveTo(block.coords, elements * 3 * block.kind.nodes);
    moveTo(block.values, elements * valueCount);
    moveTo(block.lines, elements);
  }

  // What a view leaves of its reserve was never touched, so it holds no memory (the pages of an
  // array are faulted in as it is filled): it leaves the budget's count but stays reserved. Copying
  // the array to its size instead cleared and filled fresh pages for every value again.
  template <typename T>
  void giveBackUnused(const std::vector<T>& v) {
    allocated_ -= (v.capacity() - v.size()) * sizeof(T);
  }

  PosElementBlock& blockFor(PosView& view, ViewState& state, const PosElementKind& kind) {
    int& index = state.blockOfSlot[kind.slot()];
    if (index < 0) {
      index = static_cast<int>(view.blocks.size());
      view.blocks.push_back(PosElementBlock{kind, {}, {}, {}});
    }
    return view.blocks[index];
  }

  void readElement(PosView& view, ViewState& state, const PosElementKind& kind, const char* at,
                   std::int64_t line) {
    PosElementBlock& block = blockFor(view, state, kind);
    // Coordinates: node by node (x, y, z), as gmsh writes them (its own lists keep all x, then all y, all z).
    if (!scan_.accept('(')) scan_.failExpected("'(' and the nodes' coordinates", "after " + kind.code());
    std::array<double, 3 * kMaxNodes> xyz;
    const int coordinates = 3 * kind.nodes;
    int read = 0;
    for (;;) {
      const double value = scan_.number("in the coordinates of this element");
      if (read < coordinates) xyz[read] = value;
      ++read;
      if (scan_.acceptNext(',')) continue;
      if (scan_.acceptNext(')')) break;
      failAfterNumber(')', "coordinates of this element");
    }
    if (read != coordinates)
      scan_.failAt(
          at, fmt::format("{} ({}) has {} nodes: expected {} coordinates (x, y, z of each node), found {}",
                          kind.code(), kind.description(), kind.nodes, coordinates, read));
    if (!scan_.accept('{')) scan_.failExpected("'{' and the values", "after the coordinates of this element");
    // Values: per step, per node, per component, straight into the block.
    const std::size_t perStep = static_cast<std::size_t>(kind.nodes * kind.components);
    const std::size_t first = block.values.size();
    reserveFor(block.values, state.stepsKnown ? perStep * view.stepCount : perStep, at);
    for (;;) {
      const double value = scan_.number("in the values of this element");
      if (std::abs(value) > FLT_MAX) failFloatRange(value);
      if (block.values.size() == block.values.capacity()) reserveFor(block.values, 1, at);
      block.values.push_back(static_cast<float>(value));
      if (scan_.acceptNext(',')) continue;
      if (scan_.acceptNext('}')) break;
      failAfterNumber('}', "values of this element");
    }
    if (!scan_.acceptNext(';')) scan_.failExpected("';'", "after the values of this element");
    checkSteps(view, state, kind, block.values.size() - first, at, line);
    reserveFor(block.coords, coordinates, at);
    block.coords.insert(block.coords.end(), xyz.begin(), xyz.begin() + coordinates);
    reserveFor(block.lines, 1, at);
    block.lines.push_back(line);
    if (view.blocks.size() == 1) {
      if (block.lines.size() == 1) state.firstElement = at;
      if (block.lines.size() == kSampleElements) reserveForView(block, state, block.values.size() - first);
    }
  }

  void checkSteps(PosView& view, ViewState& state, const PosElementKind& kind, std::size_t count,
                  const char* at, std::int64_t line) {
    const std::size_t perStep = static_cast<std::size_t>(kind.nodes * kind.components);
    if (!state.stepsKnown && count % perStep == 0 && count / perStep <= kMaxSteps) {
      view.stepCount = static_cast<int>(count / perStep);
      state.stepsKnown = true;
      state.stepsFrom = line;
      return;
    }
    if (state.stepsKnown && count == perStep * view.stepCount) return;
    const std::string what =
        fmt::format("{} ({}) takes {} per time step ({} at each of its {})", kind.code(), kind.description(),
                    plural(perStep, "value", "values"), plural(kind.components, "component", "components"),
                    plural(kind.nodes, "node", "nodes"));
    if (!state.stepsKnown && count / perStep > kMaxSteps)
      scan_.failAt(at, fmt::format("{}: found {} values, more than {} steps", what, count, kMaxSteps));
    if (!state.stepsKnown)
      scan_.failAt(at,
                   fmt::format("{}: found {}, not a whole number of steps; check the element's code and its "
                               "values",
                               what, plural(count, "value", "values")));
    scan_.failAt(
        at, fmt::format("{}, and view \"{}\" has {} ({} at line {}): expected {}, found {}; every element "
                        "of a view needs a value at each node for every step",
                        what, view.name, plural(view.stepCount, "step", "steps"),
                        state.stepsFromTime ? "from its TIME list" : "as its first element has",
                        state.stepsFrom, perStep * view.stepCount, count));
  }

  void readTime(PosView& view, ViewState& state, const char* at, std::int64_t line) {
    if (view.timesGiven)
      scan_.failAt(at,
                   fmt::format("view \"{}\" has a second TIME list (the first is at line {}): give one list "
                               "with a time per step",
                               view.name, state.timeLine));
    if (!scan_.accept('{')) scan_.failExpected("'{' and the times", "after TIME");
    for (;;) {
      reserveFor(view.times, 1, at);
      view.times.push_back(scan_.number("in the TIME list"));
      const char c = scan_.peek();
      if (c == '}') break;
      if (c != ',') failAfterNumber('}', "TIME list");
      scan_.accept(',');
    }
    scan_.accept('}');
    if (!scan_.accept(';')) scan_.failExpected("';'", "after the TIME list");
    view.timesGiven = true;
    state.timeLine = line;
    const std::size_t times = view.times.size();
    if (!state.stepsKnown) {
      view.stepCount = static_cast<int>(times);
      state.stepsKnown = true;
      state.stepsFromTime = true;
      state.stepsFrom = line;
    } else if (times != static_cast<std::size_t>(view.stepCount)) {
      scan_.failAt(
          at, fmt::format("TIME gives {}, but the elements of view \"{}\" have {} (its first element at "
                          "line {}): give one time per step",
                          plural(times, "time", "times"), view.name, plural(view.stepCount, "step", "steps"),
                          state.stepsFrom));
    }
  }

  // T2(x, y, style){"text", ...}; and T3(x, y, z, style){...}: read to be skipped.
  void skipText(int numbers) {
    if (!scan_.accept('(')) scan_.failExpected("'('", "after a text annotation (T2, T3)");
    for (int i = 0; i < numbers; ++i) {
      scan_.number("in the position of this text annotation");
      if (i + 1 < numbers && !scan_.accept(','))
        scan_.failExpected("','", "between the numbers of this text annotation");
    }
    if (!scan_.accept(')')) scan_.failExpected("')'", "after the position of this text annotation");
    if (!scan_.accept('{'))
      scan_.failExpected("'{' and the text", "after the position of this text annotation");
    do {
      scan_.quotedString("in this text annotation");
    } while (scan_.accept(','));
    if (!scan_.accept('}')) scan_.failExpected("'}'", "after the text of this annotation");
    if (!scan_.accept(';')) scan_.failExpected("';'", "after this text annotation");
  }

  // After a number, neither ',' nor the list's end: an expression, a typo or a truncated file.
  [[noreturn]] void failAfterNumber(char close, std::string_view list) {
    const char c = scan_.peek();
    if (c != '\0' &&
        (std::isalpha(static_cast<unsigned char>(c)) || std::strchr("+-*/^()%<>=!?&|.", c) != nullptr))
      scan_.failAt(scan_.numberStart(),
                   fmt::format("expected a number in the {}, found {}: lancer reads plain numbers, not gmsh "
                               "expressions",
                               list, describeAt(scan_.numberStart())));
    scan_.failExpected(fmt::format("',' or '{}'", close), fmt::format("in the {}", list));
  }

  [[noreturn]] void failFloatRange(double value) {
    scan_.failAt(
        scan_.numberStart(),
        fmt::format("the value {:g} is beyond the range of a float (magnitude {:g}), in which lancer "
                    "keeps values: rescale the field (change its unit)",
                    value, FLT_MAX));
  }

  PosScanner scan_;
  const char* limit_;  // the end of the bytes this parser reads (a piece's: the next piece's start)
  PosFile result_;
  std::uint64_t allocated_ = 0;
  std::span<PosPiece> pieces_;
  std::span<std::thread> threads_;
  std::size_t nextPiece_ = 0;
};

// The threads parsing pieces: told to stop and waited for when the serial parse ends, however it ends.
class PieceThreads {
 public:
  explicit PieceThreads(std::size_t count) { threads_.reserve(count); }
  ~PieceThreads() {
    cancel_.store(true, std::memory_order_relaxed);
    for (std::thread& thread : threads_)
      if (thread.joinable()) thread.join();
  }
  PieceThreads(const PieceThreads&) = delete;
  PieceThreads& operator=(const PieceThreads&) = delete;

  void start(std::span<const char> bytes, const std::string& name, PosPiece& piece) {
    threads_.emplace_back(
        [this, bytes, &name, &piece] { PosParser(bytes, name).parsePiece(piece, cancel_); });
  }
  std::span<std::thread> threads() { return threads_; }

 private:
  std::vector<std::thread> threads_;
  std::atomic<bool> cancel_{false};
};

}  // namespace

std::size_t PosView::elementCount() const {
  std::size_t count = 0;
  for (const PosElementBlock& block : blocks) count += block.elementCount();
  return count;
}

int PosView::components() const {
  int components = 0;
  for (const PosElementBlock& block : blocks) {
    if (components != 0 && block.kind.components != components) return 0;
    components = block.kind.components;
  }
  return components;
}

PosFile readPosFromMemory(std::span<const char> bytes, const std::string& nameForErrors, int threads) {
  const std::size_t pieces =
      std::min(static_cast<std::size_t>(resolveThreadCount(threads)), bytes.size() / kMinPosPieceBytes);
  PosParser parser(bytes, nameForErrors);
  if (pieces <= 1) return parser.parse();
  const std::vector<const char*> starts = posPieceStarts(bytes, pieces);
  std::vector<PosPiece> parsed(starts.size());
  for (std::size_t i = 0; i < starts.size(); ++i) {
    parsed[i].begin = starts[i];
    parsed[i].limit = i + 1 < starts.size() ? starts[i + 1] : bytes.data() + bytes.size();
  }
  PieceThreads pieceThreads(parsed.size());
  for (PosPiece& piece : parsed) pieceThreads.start(bytes, nameForErrors, piece);
  parser.usePieces(parsed, pieceThreads.threads());
  return parser.parse();
}

PosFile readPosFile(const std::string& path, int threads) {
  const MappedFile file(path, ".pos file");
  return readPosFromMemory(file.bytes(), path, threads);
}

}  // namespace lancer
