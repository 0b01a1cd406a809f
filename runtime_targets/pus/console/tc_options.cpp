// The command-line declaration of one telecommand and the help text of its fields.
#include "console/tc_options.h"

namespace smcbip::pus::console {
namespace {

/// A single-valued option kept as text, remembered as given.
void add_text_option(CLI::App& app, const std::string& name, std::optional<std::string>& target,
                     const std::string& help, const std::string& type) {
  app.add_option_function<std::string>(
         name, [&target](const std::string& text) { target = text; }, help)
      ->type_name(type);
}

/// A field option taking one or more words per use, repeatable.
void add_list_option(CLI::App& app, const std::string& name, std::vector<std::string>& target,
                     const std::string& help, const std::string& type) {
  app.add_option(name, target, help)
      ->expected(1, CLI::detail::expected_max_vector_size)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
      ->type_name(type);
}

}  // namespace

void register_tc_options(CLI::App& app, TcWords& words) {
  app.add_option("SERVICE", words.service, "the service type, e.g. 17")->required()->type_name("");
  app.add_option("SUBTYPE", words.subtype, "the message subtype, e.g. 1")
      ->required()
      ->type_name("");
  add_list_option(app, "--sid", words.sids, "[3,5] [3,6]: housekeeping structure IDs", "ID");
  add_list_option(app, "--event", words.events, "[5,5] [5,6] [19,4]: event definition IDs", "ID");
  add_list_option(app, "--pmon", words.pmons, "[12,1] [12,2]: monitoring definition IDs", "ID");
  add_list_option(app, "--param", words.params, "[20,1]: parameter IDs; [20,3]: ID=VALUE pairs",
                  "ID[=VALUE]");
  add_text_option(app, "--function", words.function, "[8,1]: the function ID", "ID");
  add_list_option(app, "--arg", words.args, "[8,1]: function arguments", "ID=VALUE");
  add_text_option(app, "--rate", words.rate, "[9,1]: the rate exponent (0..255)", "N");
  add_list_option(app, "--release", words.releases,
                  "[11,4]: a TC released at an on-board time (CUC seconds, optionally :FINE)",
                  "TIME=HEX");
  add_list_option(app, "--action", words.actions, "[19,1]: a TC run when an event occurs",
                  "EVENT=HEX");
  add_text_option(app, "--repo", words.repo,
                  "[23,x]: the repository path, under the repository root (default: the root)",
                  "PATH");
  add_text_option(app, "--file", words.file, "[23,x]: the file name", "NAME");
  add_text_option(app, "--size", words.size, "[23,1]: the maximum file size (octets)", "N");
  add_text_option(app, "--operation", words.operation, "[23,14]: the operation ID", "ID");
  add_text_option(app, "--to-repo", words.to_repo, "[23,14]: the target repository path", "PATH");
  add_text_option(app, "--to-file", words.to_file, "[23,14]: the target file name", "NAME");
  add_text_option(app, "--apid", words.apid, "the application process ID (default 0)", "N");
  add_text_option(app, "--seq", words.seq,
                  "the packet sequence count (default 0; in a script "
                  "one more than the previous TC of the same APID)",
                  "N");
  add_text_option(app, "--source", words.source, "the source ID (default 0)", "N");
  add_text_option(app, "--ack", words.ack,
                  "acknowledgement flags: letters of a (acceptance), s (start), p (progress), "
                  "c (completion), 'none', or a number 0..15 (default aspc)",
                  "FLAGS");
}

std::string tc_syntax_help() {
  return "Telecommands (numbers in decimal or 0x hex):\n"
         "  3 5|6 --sid ID...            enable/disable periodic housekeeping reports\n"
         "  5 5|6 --event ID...          enable/disable event reports\n"
         "  8 1 --function ID [--arg ID=VALUE...]   perform a function\n"
         "  9 1 --rate N                 set the time report generation rate (2^N periods)\n"
         "  11 4 --release TIME=HEX...   insert activities (TIME: seconds[:fine], HEX: a TC)\n"
         "  12 1|2 --pmon ID...          enable/disable parameter monitoring definitions\n"
         "  17 1                         are-you-alive connection test\n"
         "  19 1 --action EVENT=HEX...   add event-action definitions (HEX: a TC)\n"
         "  19 4 --event ID...           enable event-action definitions\n"
         "  20 1 --param ID...           report parameter values\n"
         "  20 3 --param ID=VALUE...     set parameter values\n"
         "  23 1 [--repo PATH] --file NAME --size N   create a file\n"
         "  23 2|3 [--repo PATH] --file NAME          delete a file / report its attributes\n"
         "  23 14 --operation ID [--repo PATH] --file NAME [--to-repo PATH] --to-file NAME\n"
         "                               copy a file\n"
         "Each takes --apid N, --seq N, --source N and --ack FLAGS for its header.\n";
}

}  // namespace smcbip::pus::console
