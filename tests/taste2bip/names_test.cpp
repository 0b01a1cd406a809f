#include "taste2bip/names.h"

#include <gtest/gtest.h>

namespace smcbip::taste2bip {
namespace {

TEST(BipIdentifier, TasteNamesBecomeIdentifiers) {
  EXPECT_EQ(bip_identifier("T-INTEGER"), "T_INTEGER");
  EXPECT_EQ(bip_identifier("TASTE-BasicTypes"), "TASTE_BasicTypes");
  EXPECT_EQ(bip_identifier("pulse"), "pulse");
  EXPECT_EQ(bip_identifier("2nd stage"), "_2nd_stage");
  EXPECT_EQ(bip_identifier(""), "_");
}

TEST(BipIdentifier, KeywordsGetAnUnderscore) {
  EXPECT_EQ(bip_identifier("end"), "end_");
  EXPECT_EQ(bip_identifier("port"), "port_");
  EXPECT_EQ(bip_identifier("data"), "data_");
  EXPECT_EQ(bip_identifier("ending"), "ending");
}

}  // namespace
}  // namespace smcbip::taste2bip
