// `lancer render ... -o -`: the picture goes to stdout as a PNG. It is written to a temporary file
// first, as any output is (band by band, atomically), then copied to stdout once complete: a
// failed or interrupted render sends nothing, and the PNG writer needs no seekable stream.
#pragma once

#include <string>

namespace lancer::cli {

class PipedOutput {
 public:
  // Refuses a terminal as stdout (InputError at "-o"), then makes the temporary file (in $TMPDIR,
  // else /tmp).
  PipedOutput();
  ~PipedOutput();  // removes the temporary file
  PipedOutput(const PipedOutput&) = delete;
  PipedOutput& operator=(const PipedOutput&) = delete;

  // The file to render into: a .png.
  const std::string& path() const { return path_; }
  // Copies the finished file to stdout. Throws InputError when stdout refuses it.
  void send() const;

 private:
  std::string path_;
};

// The output of a command given no -o (nor render.output): the input's name with `extension`, in
// the current folder (part.msh -> part.png; a step pattern "result_*.msh" -> result.png).
std::string outputNamedAfter(const std::string& input, const std::string& extension);

}  // namespace lancer::cli
