// Output files that are either the old file or the complete new one, never a half-written mix:
// every writer in lancer (images, animations) writes through AtomicFileWriter.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <span>
#include <string>

namespace lancer {

// Writes to a temporary file beside the target (".NAME.tmp-XXXXXX" in the same folder, so the final
// rename stays within one file system), then commit() flushes, fsyncs, closes and renames it over
// the target. Any failure, or destruction without commit(), removes the temporary file and leaves an
// existing target untouched. Failures are InputErrors naming the target, e.g.
//   "out/a.png: error: cannot write here: the folder 'out' does not exist"
// The new file gets the existing target's permission bits, or 0666 less the umask.
class AtomicFileWriter {
 public:
  // Creates the temporary file now, so a bad folder fails before any expensive work.
  explicit AtomicFileWriter(std::string targetPath);
  ~AtomicFileWriter();
  AtomicFileWriter(const AtomicFileWriter&) = delete;
  AtomicFileWriter& operator=(const AtomicFileWriter&) = delete;

  // Appends bytes. Never throws, so C callbacks (libpng, giflib) can call it; returns false once any
  // write has failed (the first error is kept and reported by commit()).
  bool write(const void* data, std::size_t size) noexcept;
  bool write(std::span<const std::uint8_t> bytes) noexcept { return write(bytes.data(), bytes.size()); }
  // Writes bytes at `offset` from the start of the file (past the end leaves a hole of zeros, filled
  // later); a following write() continues after them. For formats that store rows bottom-up.
  bool writeAt(std::uint64_t offset, const void* data, std::size_t size) noexcept;

  // When a write has failed: removes the temporary file and throws the InputError commit() would,
  // so a writer that streams stops at the first failure instead of after the whole image.
  void throwIfFailed();

  // Publishes the file, or throws InputError (after removing the temporary file).
  void commit();
  // Removes the temporary file; the target is untouched. Called by the destructor if not committed.
  void discard() noexcept;

  const std::string& targetPath() const { return targetPath_; }
  const std::string& tempPath() const { return tempPath_; }
  bool failed() const { return errorNumber_ != 0; }

 private:
  [[noreturn]] void failAndThrow(const std::string& what, int errorNumber);

  std::string targetPath_;
  std::string tempPath_;
  int signalSlot_ = -1;  // this file's entry for removePendingTemporaryFiles, -1 if none
  std::FILE* stream_ = nullptr;
  int errorNumber_ = 0;  // errno of the first failed write
  bool targetExisted_ = false;
};

// For a SIGINT / SIGTERM handler: unlinks the temporary files of every AtomicFileWriter alive now.
// Async-signal-safe (only unlink() on fixed buffers); up to 64 concurrent writers are tracked. The
// caller then re-raises the signal, e.g.
//   void onInterrupt(int s) { lancer::removePendingTemporaryFiles(); signal(s, SIG_DFL); raise(s); }
void removePendingTemporaryFiles() noexcept;

// Throws the InputError an AtomicFileWriter for `path` would (its folder missing or read-only, a folder
// in its place), changing nothing: for an output written after a long render, checked before it.
void requireWritable(const std::string& path);

// True when `a` and `b` name one file (after resolving `.`, `..` and symbolic links), written or not.
bool sameOutputPath(const std::string& a, const std::string& b);

// The common case: the whole file is in memory.
void writeFileAtomically(const std::string& path, std::span<const std::uint8_t> bytes);

}  // namespace lancer
