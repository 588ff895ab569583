#include "lancer/mesh/msh/text_number.hpp"

namespace lancer {

std::string quoteTokenForMessage(std::string_view token) {
  std::string shown;
  for (char c : token.substr(0, 32)) {
    const auto u = static_cast<unsigned char>(c);
    shown += (u >= 32 && u < 127) ? c : '?';
  }
  if (token.size() > 32) shown += "...";
  return "'" + shown + "'";
}

}  // namespace lancer
