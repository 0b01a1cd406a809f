// Parsing script lines with the encode command's declaration, and locating what they refuse.
#include "console/script.h"

#include <algorithm>
#include <charconv>

#include "console/hex.h"

namespace smcbip::pus::console {
namespace {

struct Word {
  std::string text;
  std::uint32_t column = 0;
};

/// The words of a line up to a '#' that starts a word, with their 1-based columns.
std::vector<Word> split_words(std::string_view text) {
  std::vector<Word> words;
  std::size_t i = 0;
  while (i < text.size()) {
    if (text[i] == ' ' || text[i] == '\t' || text[i] == '\r') {
      ++i;
      continue;
    }
    if (text[i] == '#') break;
    const std::size_t start = i;
    while (i < text.size() && text[i] != ' ' && text[i] != '\t' && text[i] != '\r') ++i;
    words.push_back(
        {std::string(text.substr(start, i - start)), static_cast<std::uint32_t>(start + 1)});
  }
  return words;
}

bool is_option(const std::string& word) { return word.size() > 1 && word[0] == '-'; }

/// The column of `word` given to `option` (SERVICE and SUBTYPE are the first two plain words),
/// of the option itself when `word` is empty; the end of the line when neither is there.
std::uint32_t locate(const std::vector<Word>& words, const std::string& option,
                     const std::string& word, std::uint32_t end_column) {
  std::string current;  // the option the words at this point belong to
  std::size_t plain = 0;
  for (const Word& w : words) {
    if (is_option(w.text)) {
      current = w.text.substr(0, w.text.find('='));
      if (current == option && (word.empty() || w.text == option + "=" + word)) return w.column;
      continue;
    }
    const std::string owner = current.empty() ? (plain++ == 0 ? "SERVICE" : "SUBTYPE") : current;
    if (owner == option && w.text == word) return w.column;
  }
  return end_column;
}

/// The column CLI11's message is about: the first option word it names, else the line's end.
std::uint32_t locate_cli_error(const std::vector<Word>& words, const std::string& message,
                               std::uint32_t end_column) {
  for (const Word& w : words) {
    const std::string name = w.text.substr(0, w.text.find('='));
    if (is_option(w.text) && message.find(name) != std::string::npos) return w.column;
  }
  return end_column;
}

ScriptError located(std::uint32_t line, std::uint32_t column, const std::string& message) {
  return {line, column, message};
}

/// `wait MS`: the pause, or the error at the word that is not a number of milliseconds.
void parse_wait(const std::vector<Word>& words, std::uint32_t line, std::uint32_t end_column,
                LineResult& result) {
  const std::string expected =
      "wait: expected a number of milliseconds from 0 to " + std::to_string(kMaxWaitMs);
  if (words.size() != 2) {
    const std::uint32_t column = words.size() < 2 ? end_column : words[2].column;
    const std::string got = words.size() < 2 ? "nothing" : "'" + words[2].text + "' after it";
    result.errors.push_back(located(line, column, expected + ", got " + got));
    return;
  }
  const std::string& text = words[1].text;
  std::uint64_t ms = 0;
  const auto [stop, error] = std::from_chars(text.data(), text.data() + text.size(), ms);
  if (error != std::errc() || stop != text.data() + text.size() || ms > kMaxWaitMs) {
    result.errors.push_back(located(line, words[1].column, expected + ", got '" + text + "'"));
    return;
  }
  result.wait = std::chrono::milliseconds(ms);
}

/// `raw HEX`: the octets, or the error at the word that is not hex.
void parse_raw(const std::vector<Word>& words, std::uint32_t line, std::uint32_t end_column,
               LineResult& result) {
  if (words.size() != 2) {
    const std::uint32_t column = words.size() < 2 ? end_column : words[2].column;
    const std::string got = words.size() < 2 ? "nothing" : "'" + words[2].text + "' after it";
    result.errors.push_back(located(line, column, "raw: expected the octets in hex, got " + got));
    return;
  }
  std::vector<std::uint8_t> bytes;
  HexError error;
  const bool parsed = parse_hex(words[1].text, bytes, error);
  if (!parsed || bytes.empty()) {
    const auto column = words[1].column + static_cast<std::uint32_t>(parsed ? 0 : error.offset);
    result.errors.push_back(
        located(line, column, "raw: expected " + (parsed ? "at least one octet" : error.expected)));
    return;
  }
  result.raw = std::move(bytes);
}

}  // namespace

LineResult parse_line(std::string_view text, std::uint32_t line, const Config& config) {
  LineResult result;
  std::vector<Word> words = split_words(text);
  if (words.empty()) return result;
  const auto end_column = static_cast<std::uint32_t>(text.find_last_not_of(" \t\r") + 2);
  if (words.front().text == "wait") {
    parse_wait(words, line, end_column, result);
    return result;
  }
  if (words.front().text == "raw") {
    parse_raw(words, line, end_column, result);
    return result;
  }
  if (words.front().text == "encode") words.erase(words.begin());
  CLI::App app;
  app.set_help_flag();
  app.allow_extras();
  TcWords tc_words;
  register_tc_options(app, tc_words);
  std::vector<std::string> args;
  for (auto w = words.rbegin(); w != words.rend(); ++w) args.push_back(w->text);
  try {
    app.parse(args);
  } catch (const CLI::ArgumentMismatch& e) {  // "--sid: 1 required ID missing"
    const std::string what = e.what(), option = what.substr(0, what.find(':'));
    result.errors.push_back(located(line, locate_cli_error(words, what, end_column),
                                    option + ": expected a value after it, got none"));
    return result;
  } catch (const CLI::ParseError& e) {
    result.errors.push_back(
        located(line, locate_cli_error(words, e.what(), end_column),
                std::string("expected SERVICE SUBTYPE and the TC's fields: ") + e.what()));
    return result;
  }
  if (!app.remaining().empty()) {
    const std::string extra = app.remaining().front();
    const auto it = std::find_if(words.begin() + std::min<std::size_t>(2, words.size()),
                                 words.end(), [&](const Word& w) { return w.text == extra; });
    result.errors.push_back(located(line, it == words.end() ? end_column : it->column,
                                    "expected a field or header option of the TC (see pus-console "
                                    "encode --help), got '" +
                                        extra + "'"));
    return result;
  }
  try {
    result.tc = build_tc(tc_words, config);
    encode_tc(result.tc.tc, config);  // what the library refuses is refused here, located
    result.has_tc = true;
  } catch (const TcSyntaxError& e) {
    const std::uint32_t column =
        e.option() == "TC" ? words.front().column : locate(words, e.option(), e.word(), end_column);
    result.errors.push_back(located(line, column, e.what()));
  }
  return result;
}

void Sequencer::number(BuiltTc& built) {
  PrimaryHeader& primary = built.tc.primary;
  if (!built.seq_given) primary.sequence_count = next_[primary.apid];
  next_[primary.apid] =
      static_cast<std::uint16_t>((primary.sequence_count + 1) & kMaxSequenceCount);
}

ParsedScript parse_script(std::string_view text, const Config& config) {
  ParsedScript script;
  Sequencer sequencer;
  std::uint32_t line = 0;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    ++line;
    LineResult result = parse_line(text.substr(start, end - start), line, config);
    for (ScriptError& e : result.errors) script.errors.push_back(std::move(e));
    if (result.wait) script.tcs.push_back({Telecommand{}, {}, line, result.wait});
    if (result.raw) script.tcs.push_back({Telecommand{}, *result.raw, line, std::nullopt, true});
    if (result.has_tc) {
      sequencer.number(result.tc);
      ParsedScript::Entry entry{result.tc.tc, encode_tc(result.tc.tc, config), line, std::nullopt};
      entry.tc.primary.data_length = static_cast<std::uint16_t>(entry.bytes.size() - 7);
      script.tcs.push_back(std::move(entry));
    }
    if (end == text.size()) break;
    start = end + 1;
  }
  if (!script.errors.empty()) script.tcs.clear();
  return script;
}

}  // namespace smcbip::pus::console
