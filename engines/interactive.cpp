#include "engines/interactive.h"

#include <charconv>
#include <string>

namespace smcbip::engines {

namespace {

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

}  // namespace

std::optional<std::size_t> prompt_choice(std::ostream& out, std::istream* in, std::size_t count) {
  if (in == nullptr) return std::nullopt;
  for (;;) {
    // A whole line, so that the trace stays line-oriented when the answers come from a pipe.
    out << "choose an item [0-" << count - 1 << "] (q to quit):" << std::endl;
    std::string line;
    if (!std::getline(*in, line)) return std::nullopt;
    const std::string answer = trimmed(line);
    if (answer == "q" || answer == "quit") return std::nullopt;
    std::size_t index = 0;
    const char* end = answer.data() + answer.size();
    const auto [ptr, ec] = std::from_chars(answer.data(), end, index);
    if (ec == std::errc() && ptr == end && !answer.empty() && index < count) return index;
    out << "'" << answer << "' is not a number between 0 and " << count - 1 << "\n";
  }
}

}  // namespace smcbip::engines
