// The new translation of the watchdog design, loaded beside the original.
#include "tests/taste2bip/watchdog_translation.h"

#include <gtest/gtest.h>

#include <regex>
#include <vector>

#include "taste2bip/translate/package.h"
#include "taste2bip/translate/read_design.h"
#include "tests/taste2bip/shared_data.h"
#include "tests/taste2bip/watchdog_model.h"

namespace smcbip::taste2bip::test {

std::optional<std::string> translated_package(
    std::string& why, const std::map<std::string, std::string>& behaviours) {
  DesignFiles files;
  files.interface_view =
      (shared_data_dir() / "esrocos-mc_watchdog" / "TasteModel" / "InterfaceView.aadl").string();
  bipc::SourceFiles sources;
  bipc::Diagnostics diags;
  std::vector<std::string> notes;
  std::optional<Packages> packages;
  if (std::optional<Design> design = read_design(files, sources, diags, notes)) {
    design->behaviours = behaviours;
    packages = translate(*design, PackageOptions{}, diags);
  }
  if (!packages) {
    why = diags.format(sources);
    return std::nullopt;
  }
  return packages->nominal;
}

std::filesystem::path watchdog_atom_file() {
  return std::filesystem::path(SMCBIP_SOURCE_DIR) / "tests/taste2bip/watchdog/watchdog_atom.bip";
}

namespace {

/// Replaces the one match of `pattern` in `text` by `replacement`; false (and `why` set) when
/// there is not exactly one.
bool replace_once(std::string& text, const std::string& pattern, const std::string& replacement,
                  std::string& why) {
  const std::regex re(pattern);
  const auto found =
      std::distance(std::sregex_iterator(text.begin(), text.end(), re), std::sregex_iterator());
  if (found != 1) {
    why = "lost heartbeat: `" + pattern + "` matches " + std::to_string(found) +
          " times in the JoystickDriver atom, expected once";
    return false;
  }
  text = std::regex_replace(text, re, replacement);
  return true;
}

}  // namespace

std::optional<std::string> with_lost_heartbeat(const std::string& package, std::string& why) {
  const std::string head = "  atom type JoystickDriver()\n", tail = "\n  end\n";
  const std::size_t begin = package.find(head);
  const std::size_t end = begin == std::string::npos ? begin : package.find(tail, begin);
  if (end == std::string::npos) {
    why = "lost heartbeat: no atom type JoystickDriver in the package";
    return std::nullopt;
  }
  std::string atom = package.substr(begin, end + 1 - begin);  // up to its last transition
  const bool ok = replace_once(atom, R"(atom type JoystickDriver\(\)\n)",
                               "atom type JoystickDriver()\n    clock t unit millisecond\n", why) &&
                  replace_once(atom, R"(\n    place ([^\n]*)\n)",
                               "\n    port Port silent()\n    @fault\n    port Port fault1()\n"
                               "    place $1, l5, l6\n",
                               why) &&
                  replace_once(atom, R"(\n    initial to Wait, ready\n)",
                               "\n    initial to Wait, ready do { t = 0; }\n", why);
  if (!ok) return std::nullopt;
  atom +=
      "    on fault1 from Wait, ready to l5 provided (t < 100) lazy\n"
      "    on silent from l5 to Wait, ready provided (t >= 150) lazy do { t = 0; }\n"
      "    on step_in from l5 to l6 eager\n"
      "    on step_return from l6 to l5\n";
  return package.substr(0, begin) + atom + package.substr(end + 1);
}

WatchdogObservation translation_observation(bool watchdog_calls) {
  WatchdogObservation o = watchdog_observation(WatchdogNaming::Translation, watchdog_calls, false);
  o.erased_data.insert("*.dropped");
  return o;
}

BothModels load_both() {
  BothModels both;
  std::string why;
  both.original = load_watchdog_original(why);
  EXPECT_TRUE(both.original) << why;
  if (both.original) remove_fault_transitions(*both.original);
  const std::optional<std::string> package = translated_package(why);
  EXPECT_TRUE(package) << why;
  if (package) both.translation = load_bip_text(*package, "taste.bip", "Syst()", why);
  EXPECT_TRUE(!package || both.translation) << why;
  return both;
}

}  // namespace smcbip::taste2bip::test
