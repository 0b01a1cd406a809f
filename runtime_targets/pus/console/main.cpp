// pus-console: the ground side of the PUS target. Encodes TCs, decodes TCs and TMs into the
// console table, and runs scripts or an interactive session over a UDP link.
//
// Exit codes: 0 success, 2 input or usage error (a malformed packet, a refused script line),
// 3 internal error.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <fstream>
#include <iostream>
#include <iterator>
#include <memory>
#include <sstream>
#include <string>
#include <utility>

#include "bipc/exit_codes.h"
#include "bipc/options.h"
#include "bipc/output_file.h"
#include "bipc/tool_main.h"
#include "console/console.h"

namespace {

using namespace smcbip;
using namespace smcbip::pus;
using namespace smcbip::pus::console;

struct Arguments {
  TcWords words;
  std::string out;
  std::vector<std::string> hex;  // the words of HEX, joined by spaces
  std::string in;
  std::string script;
  LinkOptions link;
};

std::string read_file(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw InputError("cannot read this file", ErrorLocation{path});
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

void write_file(const std::string& path, const std::string& text) {
  std::string error;
  if (!bipc::write_file_atomically(path, text, error)) throw InputError(error);
}

/// Refuses a --log or --packet-log that could not be written before anything is sent.
void check_writable(const LinkOptions& options) {
  for (const auto& [option, path] :
       {std::pair{"--log", &options.log}, std::pair{"--packet-log", &options.packet_log}}) {
    std::string target, error;
    if (!path->empty() && !bipc::output_target(*path, target, error)) {
      throw UsageError(std::string(option) + ": " + error);
    }
  }
}

void write_logs(const LinkOptions& options, const Session& session) {
  if (!options.log.empty()) write_file(options.log, session.table());
  if (!options.packet_log.empty()) write_file(options.packet_log, session.packets());
}

int encode_command(const Arguments& args) {
  const std::vector<std::uint8_t> bytes = encode_words(args.words, Config{});
  std::cout << to_hex(bytes) << "\n";
  if (!args.out.empty()) write_file(args.out, std::string(bytes.begin(), bytes.end()));
  return exit_codes::kSuccess;
}

int decode_command(const Arguments& args) {
  if (args.hex.empty() == args.in.empty()) throw UsageError("decode: expected HEX or --in FILE");
  std::vector<std::uint8_t> bytes;
  if (args.in.empty()) {
    std::string text;
    for (const std::string& word : args.hex) text += (text.empty() ? "" : " ") + word;
    bytes = bytes_of_hex(text, "HEX");
  } else {
    const std::string data = read_file(args.in);
    bytes.assign(data.begin(), data.end());
  }
  const Row row = decode_bytes(bytes, Config{});
  std::cout << table_header() << "\n" << format_row(row) << "\n";
  return exit_codes::kSuccess;
}

int script_command(const Arguments& args) {
  const ParsedScript script = parse_script(read_file(args.script), Config{});
  for (const ScriptError& e : script.errors) std::cerr << format_error(args.script, e) << "\n";
  if (!script.errors.empty()) return exit_codes::kInputError;
  check_writable(args.link);
  const std::unique_ptr<Link> link = open_link(args.link);
  Session session(Config{}, std::cout, link.get());
  run_script(script, session, std::chrono::milliseconds(args.link.wait_ms));
  write_logs(args.link, session);
  return exit_codes::kSuccess;
}

int interactive_command(const Arguments& args) {
  check_writable(args.link);
  const std::unique_ptr<Link> link = open_link(args.link);
  if (::isatty(STDIN_FILENO) != 0) {
    std::cerr << "pus-console: one TC per line as for encode (see interactive --help), "
                 "'wait MS' to receive, end of input (Ctrl-D) to stop\n";
  }
  Session session(Config{}, std::cout, link.get());
  const std::size_t refused =
      run_interactive(std::cin, "<stdin>", session, std::cerr,
                      std::chrono::milliseconds(args.link.wait_ms), Config{});
  write_logs(args.link, session);
  return refused == 0 ? exit_codes::kSuccess : exit_codes::kInputError;
}

void add_commands(CLI::App& app, Arguments& args) {
  CLI::App* encode = app.add_subcommand("encode", "print a TC as hex");
  register_tc_options(*encode, args.words);
  encode->add_option("--out", args.out, "write the TC's octets to this file")->type_name("FILE");
  encode->footer(tc_syntax_help());
  CLI::App* decode = app.add_subcommand("decode", "decode one TC or TM into a table row");
  auto* hex = decode->add_option("HEX", args.hex, "the packet in hex (in one or more words)")
                  ->type_name("");
  decode->add_option("--in", args.in, "read the packet's octets from this file")
      ->type_name("FILE")
      ->excludes(hex);
  CLI::App* script = app.add_subcommand(
      "script",
      "send the TCs of a script (one encode-style TC per line, 'wait MS' to receive for MS ms "
      "before going on, '#' comments) and tabulate the TMs received; without --port, list the "
      "TCs only");
  script->add_option("FILE", args.script, "the script")->required()->type_name("");
  register_link_options(*script, args.link, false);
  script->footer(tc_syntax_help());
  CLI::App* interactive =
      app.add_subcommand("interactive",
                         "read TCs (and 'wait MS') line by line from stdin, send each and "
                         "tabulate the TMs received");
  register_link_options(*interactive, args.link, true);
  interactive->footer(tc_syntax_help());
  app.require_subcommand(0, 1);
}

int run(int argc, char** argv) {
  CLI::App app{"pus-console: the ground console of the PUS target"};
  Arguments args;
  add_commands(app, args);
  cli::add_version_flags(app, "pus-console");
  if (const int code = cli::parse_command_line(app, argc, argv); code >= 0) return code;
  if (app.get_subcommands().empty()) {
    throw UsageError("expected a command: encode, decode, script or interactive (see --help)");
  }
  const std::string command = app.get_subcommands().front()->get_name();
  if (command == "encode") return encode_command(args);
  if (command == "decode") return decode_command(args);
  if (command == "script") return script_command(args);
  return interactive_command(args);
}

}  // namespace

int main(int argc, char** argv) {
  return cli::guarded_main("pus-console", exit_codes::kJudgingCodes,
                           [&] { return run(argc, argv); });
}
