// The fuzzers' seeds are valid designs: each reads (and resolves, or flattens) without a
// diagnostic, so the fuzzers start from inputs that reach deep into the readers.
#include <gtest/gtest.h>

#include <filesystem>

#include "taste2bip/asn1/data_view.h"
#include "taste2bip/interface_view/interface_view.h"
#include "taste2bip/sdl/sdl_reader.h"
#include "tests/taste2bip/shared_data.h"

namespace smcbip::taste2bip {
namespace {

const std::filesystem::path kSeeds =
    std::filesystem::path(SMCBIP_SOURCE_DIR) / "tests" / "taste2bip" / "fuzz" / "seeds";

std::string messages(const bipc::Diagnostics& diags) {
  bipc::SourceFiles files;
  files.add("seed");
  return diags.format(files);
}

TEST(FuzzSeeds, DataViewReadsAndResolves) {
  bipc::Diagnostics diags;
  asn1::DataView view;
  asn1::read_asn1(test::file_text(kSeeds / "asn1" / "types.asn"), 0, view, diags);
  asn1::resolve(view, diags);
  EXPECT_TRUE(diags.all().empty()) << messages(diags);
  EXPECT_EQ(view.modules.size(), 2u);
}

TEST(FuzzSeeds, AadlViewReadsAndFlattens) {
  bipc::Diagnostics diags;
  const InterfaceView view = flatten(
      read_aadl_interface_view(test::file_text(kSeeds / "aadl" / "InterfaceView.aadl"), 0, diags),
      diags);
  EXPECT_TRUE(diags.all().empty()) << messages(diags);
  ASSERT_EQ(view.functions.size(), 2u);
  EXPECT_EQ(view.connections.size(), 1u);
}

TEST(FuzzSeeds, XmlViewReadsAndFlattens) {
  bipc::Diagnostics diags;
  const InterfaceView view = flatten(
      read_xml_interface_view(test::file_text(kSeeds / "xml" / "interfaceview.xml"), 0, diags),
      diags);
  EXPECT_TRUE(diags.all().empty()) << messages(diags);
  ASSERT_EQ(view.functions.size(), 2u);  // Driver and Motors: Platform only delegates
  ASSERT_EQ(view.connections.size(), 1u);
  EXPECT_EQ(view.connections[0].from.function, "Driver");
  EXPECT_EQ(view.connections[0].to.function, "Motors");
}

TEST(FuzzSeeds, SdlReads) {
  bipc::Diagnostics diags;
  const sdl::SdlFile file =
      sdl::read_sdl(test::file_text(kSeeds / "sdl" / "controller.pr"), 0, diags);
  EXPECT_TRUE(diags.all().empty()) << messages(diags);
  EXPECT_EQ(file.systems.size(), 1u);
}

}  // namespace
}  // namespace smcbip::taste2bip
