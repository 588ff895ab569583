// Writing under a file size limit (what `ulimit -f` sets, and what a full disk looks like to a
// writer), in a forked child so that the limit never reaches the test process.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

namespace lancer::test {

// Runs `writeFiles` in a forked child limited to `limitBytes` per file (RLIMIT_FSIZE), with SIGXFSZ
// ignored so that a write past the limit fails with EFBIG instead of killing the child. Returns
// what `writeFiles` returned, sent back through a pipe, or "(child failed: status N)".
std::string underFileSizeLimit(std::uint64_t limitBytes, const std::function<std::string()>& writeFiles);

}  // namespace lancer::test
