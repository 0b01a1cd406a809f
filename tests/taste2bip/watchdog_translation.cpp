// The new translation of the watchdog design, loaded beside the original.
#include "tests/taste2bip/watchdog_translation.h"

#include <gtest/gtest.h>

#include <vector>

#include "taste2bip/translate/package.h"
#include "taste2bip/translate/read_design.h"
#include "tests/taste2bip/shared_data.h"
#include "tests/taste2bip/watchdog_model.h"

namespace smcbip::taste2bip::test {

std::optional<std::string> translated_package(std::string& why) {
  DesignFiles files;
  files.interface_view =
      (shared_data_dir() / "esrocos-mc_watchdog" / "TasteModel" / "InterfaceView.aadl").string();
  bipc::SourceFiles sources;
  bipc::Diagnostics diags;
  std::vector<std::string> notes;
  std::optional<Packages> packages;
  if (std::optional<Design> design = read_design(files, sources, diags, notes)) {
    packages = translate(*design, PackageOptions{}, diags);
  }
  if (!packages) {
    why = diags.format(sources);
    return std::nullopt;
  }
  return packages->nominal;
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
