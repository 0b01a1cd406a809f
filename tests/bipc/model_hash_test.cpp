// The model hash: SHA-256 known answers, the documented byte layout, what changes the hash,
// and the extern sources read from disk.
#include "bipc/ir/model_hash.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>

#include "bipc/ir/detail/sha256.h"
#include "bipc/ir/ir_data.h"
#include "ir_data_test_util.h"

namespace smcbip::bipc {
namespace {

namespace fs = std::filesystem;
using ir::detail::Sha256;
using ir_data_test::sample_system;

std::string sha256_of(std::string_view text) {
  Sha256 sha;
  sha.update(text);
  return sha.hex_digest();
}

// FIPS 180-4 examples (NIST CSRC "Examples with intermediate values") and the empty message.
TEST(ModelHash, Sha256KnownAnswers) {
  EXPECT_EQ(sha256_of("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256_of(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256_of("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  // Fed in pieces, as model_hash feeds it.
  Sha256 pieces;
  pieces.update(std::string_view("ab"));
  pieces.update(std::string_view(""));
  pieces.update(std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t*>("c"), 1));
  EXPECT_EQ(pieces.hex_digest(), sha256_of("abc"));
  // A million 'a' (FIPS 180-4 long message).
  EXPECT_EQ(sha256_of(std::string(1'000'000, 'a')),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

std::string little_endian_u64(std::uint64_t n) {
  std::string bytes;
  for (int i = 0; i < 8; ++i) bytes += static_cast<char>((n >> (8 * i)) & 0xFF);
  return bytes;
}

/// Every value named "loc" under `data`, at any depth, set to null, and every instruction's
/// site (its seventh element) dropped.
void null_locations(nlohmann::json& data) {
  if (data.is_structured()) {
    for (auto it = data.begin(); it != data.end(); ++it) {
      if (data.is_object() && it.key() == "loc") {
        *it = nullptr;
      } else if (data.is_object() && it.key() == "instrs") {
        for (auto& instr : *it) instr.erase(6);
      } else {
        null_locations(*it);
      }
    }
  }
}

/// The IR bytes model_hash covers, spelled out from model_hash.h's description.
std::string normalised_cbor(const ir::System& s) {
  nlohmann::json data = ir::to_data(s);
  null_locations(data);
  for (auto& source : data["cpp_sources"]) {
    source = fs::path(source.get<std::string>()).filename().string();
  }
  data["cpp_include_dirs"] = nlohmann::json::array();
  data.erase("sites");
  data.erase("source_files");
  for (auto& type : data["atom_types"]) {
    for (auto& port : type["ports"]) {
      if (!port.contains("stochastic") || port["stochastic"].is_null()) continue;
      auto& file = port["stochastic"]["custom_file"];
      file = fs::path(file.get<std::string>()).filename().string();
    }
  }
  const std::vector<std::uint8_t> cbor = nlohmann::json::to_cbor(data);
  return {cbor.begin(), cbor.end()};
}

TEST(ModelHash, HashesTheDocumentedBytes) {
  const ir::System s = sample_system();
  ASSERT_FALSE(s.atom_types.empty());
  ASSERT_EQ(s.cpp_sources, std::vector<std::string>{"src/geo.cpp"});
  const ir::ExternSources sources = {{"a.cpp", "src/a.cpp", "int a;\n"}, {"a.hpp", "a.hpp", ""}};
  std::string message = normalised_cbor(s);
  EXPECT_NE(message.find("geo.cpp"), std::string::npos);
  EXPECT_EQ(message.find("src/geo.cpp"), std::string::npos);
  for (const ir::ExternSource& source : sources) {
    message += little_endian_u64(source.name.size()) + source.name +
               little_endian_u64(source.contents.size()) + source.contents;
  }
  const std::string hash = ir::model_hash(s, sources);
  EXPECT_EQ(hash, sha256_of(message));
  EXPECT_EQ(hash.size(), 64u);
  EXPECT_EQ(hash.find_first_not_of("0123456789abcdef"), std::string::npos);
  EXPECT_EQ(ir::model_hash(s, {}), sha256_of(normalised_cbor(s)));
}

TEST(ModelHash, IgnoresWhereTheModelIsStoredAndWritten) {
  const ir::System s = sample_system();
  const std::string hash = ir::model_hash(s, {});

  ir::System moved = sample_system();
  moved.cpp_sources = {"/elsewhere/geo.cpp"};
  moved.cpp_include_dirs = {"/elsewhere", "/usr/include/geo"};
  EXPECT_EQ(ir::model_hash(moved, {}), hash);

  ir::System shifted = sample_system();  // as if a comment had been added above
  for (ir::AtomType& type : shifted.atom_types) {
    for (ir::Transition& t : type.transitions) {
      t.loc.line += 3;
      for (ir::Annotation& a : t.annotations) a.loc.line += 3;
    }
    for (ir::Annotation& a : type.annotations) a.loc.line += 3;
  }
  for (ir::CompoundInstance& c : shifted.compounds) {
    for (ir::Annotation& a : c.annotations) a.loc.column += 1;
  }
  for (bipc::Location& site : shifted.sites) site.line += 3;
  shifted.source_files = {"/elsewhere/pkg.bip", "/elsewhere/dep.bip"};
  EXPECT_EQ(ir::model_hash(shifted, {}), hash);

  ir::System renamed = sample_system();
  renamed.cpp_sources = {"src/geo2.cpp"};
  EXPECT_NE(ir::model_hash(renamed, {}), hash);

  // A source's path is where it was read, not part of the identity.
  const ir::ExternSources here = {{"a.cpp", "src/a.cpp", "int a;\n"}};
  const ir::ExternSources there = {{"a.cpp", "/x/a.cpp", "int a;\n"}};
  EXPECT_EQ(ir::model_hash(s, here), ir::model_hash(s, there));
}

TEST(ModelHash, ChangesWithTheModelAndItsSources) {
  const ir::System s = sample_system();
  const ir::ExternSources sources = {{"a.cpp", "src/a.cpp", "int a = 1;\n"},
                                     {"a.hpp", "a.hpp", "extern int a;\n"}};
  const std::string hash = ir::model_hash(s, sources);
  EXPECT_EQ(ir::model_hash(sample_system(), sources), hash) << "same inputs, same hash";

  ir::System immediate = sample_system();
  immediate.atom_types[0].transitions[0].guard.instrs[1].imm.i += 1;
  EXPECT_NE(ir::model_hash(immediate, sources), hash);

  ir::ExternSources contents = sources;
  contents[0].contents = "int a = 2;\n";
  EXPECT_NE(ir::model_hash(s, contents), hash);

  ir::ExternSources name = sources;
  name[1].name = "b.hpp";
  EXPECT_NE(ir::model_hash(s, name), hash);

  ir::ExternSources order = {sources[1], sources[0]};
  EXPECT_NE(ir::model_hash(s, order), hash);

  // A byte moved across the boundary of a name and its contents changes a length.
  const ir::ExternSources left = {{"ab", "", "c"}}, right = {{"a", "", "bc"}};
  EXPECT_NE(ir::model_hash(s, left), ir::model_hash(s, right));
  EXPECT_NE(ir::model_hash(s, {{"", "", ""}}), ir::model_hash(s, {}));
}

/// A fresh directory under the system's temporary folder, removed at the end of the test.
class TempDir {
 public:
  TempDir() {
    std::string pattern = (fs::temp_directory_path() / "model_hash_XXXXXX").string();
    if (::mkdtemp(pattern.data()) != nullptr) path_ = pattern;
  }
  ~TempDir() {
    std::error_code ignored;
    if (!path_.empty()) fs::remove_all(path_, ignored);
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

void write(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
}

const char* const kExternModel =
    "@cpp(src=\"impl/lamp.cpp\", include=\"lamp.hpp,extra.hpp,stdio.h\")\n"
    "package lamp\n"
    "  port type P()\n"
    "  atom type A()\n"
    "    export port P p()\n"
    "    place S\n"
    "    initial to S\n"
    "    on p from S to S\n"
    "  end\n"
    "  compound type Top()\n"
    "    component A a()\n"
    "  end\n"
    "end\n";

TEST(ModelHash, ExternSourcesAreReadFromTheModelsFolders) {
  const TempDir dir;
  ASSERT_FALSE(dir.path().empty());
  const fs::path model = dir.path() / "model" / "lamp.bip";
  write(model, kExternModel);
  write(dir.path() / "model" / "impl" / "lamp.cpp", "int lamp() { return 1; }\n");
  write(dir.path() / "model" / "lamp.hpp", "int lamp();\n");
  write(dir.path() / "inc" / "extra.hpp", "#define EXTRA 1\n");
  write(dir.path() / "inc" / "lamp.hpp", "a header the package folder hides\n");
  std::string messages;
  const std::optional<ir::System> system = ir_data_test::load_system(model, "Top()", {}, &messages);
  ASSERT_TRUE(system.has_value()) << messages;

  const ir::ExternSources sources = ir::extern_sources_of(*system, {(dir.path() / "inc").string()});
  ASSERT_EQ(sources.size(), 3u);  // stdio.h is found nowhere: the toolchain's, left out
  EXPECT_EQ(sources[0].name, "lamp.cpp");
  EXPECT_EQ(fs::path(sources[0].path), (dir.path() / "model" / "impl" / "lamp.cpp"));
  EXPECT_EQ(sources[0].contents, "int lamp() { return 1; }\n");
  EXPECT_EQ(sources[1].name, "lamp.hpp");
  EXPECT_EQ(fs::path(sources[1].path), dir.path() / "model" / "lamp.hpp");
  EXPECT_EQ(sources[1].contents, "int lamp();\n");
  EXPECT_EQ(sources[2].name, "extra.hpp");
  EXPECT_EQ(sources[2].contents, "#define EXTRA 1\n");

  // Without the -I folder, extra.hpp is taken for a toolchain header too.
  EXPECT_EQ(ir::extern_sources_of(*system, {}).size(), 2u);

  const std::string hash = ir::model_hash(*system, sources);

  // The same files elsewhere, the model with a comment on top: the same model.
  const fs::path moved = dir.path() / "moved" / "lamp.bip";
  write(moved, "// moved\n" + std::string(kExternModel));
  fs::copy(dir.path() / "model" / "impl", dir.path() / "moved" / "impl");
  fs::copy(dir.path() / "model" / "lamp.hpp", dir.path() / "moved" / "lamp.hpp");
  const std::optional<ir::System> moved_system =
      ir_data_test::load_system(moved, "Top()", {}, &messages);
  ASSERT_TRUE(moved_system.has_value()) << messages;
  EXPECT_EQ(ir::model_hash(*moved_system,
                           ir::extern_sources_of(*moved_system, {(dir.path() / "inc").string()})),
            hash);

  write(dir.path() / "model" / "impl" / "lamp.cpp", "int lamp() { return 2; }\n");
  EXPECT_NE(
      ir::model_hash(*system, ir::extern_sources_of(*system, {(dir.path() / "inc").string()})),
      hash);

  fs::remove(dir.path() / "model" / "impl" / "lamp.cpp");
  try {
    ir::extern_sources_of(*system, {});
    ADD_FAILURE() << "a missing source was not reported";
  } catch (const ir::ExternSourceError& e) {
    EXPECT_EQ(fs::path(e.path), dir.path() / "model" / "impl" / "lamp.cpp");
    EXPECT_NE(e.message.find("no such file"), std::string::npos) << e.message;
  }
}

constexpr const char* kCustomModel =
    "package delays\n"
    "  port type Sig()\n"
    "  atom type A()\n"
    "    clock x unit millisecond\n"
    "    @stochastic(dist=\"custom\", clk=x, param=\"data/delay.cdf\")\n"
    "    port Sig go()\n"
    "    @stochastic(dist=\"custom\", clk=x, param=\"data/delay.cdf\")\n"
    "    port Sig stop()\n"
    "    place s\n"
    "    initial to s do { x = 0; }\n"
    "    on go from s to s do { x = 0; }\n"
    "    on stop from s to s do { x = 0; }\n"
    "  end\n"
    "  compound type Top()\n"
    "    component A a()\n"
    "  end\n"
    "end\n";

TEST(ModelHash, CoversTheContentsOfEmpiricalDistributions) {
  const TempDir dir;
  ASSERT_FALSE(dir.path().empty());
  const auto load = [&](const fs::path& model) {
    std::string messages;
    std::optional<ir::System> system = ir_data_test::load_system(model, "Top()", {}, &messages);
    EXPECT_TRUE(system.has_value()) << messages;
    return system;
  };
  write(dir.path() / "one" / "delays.bip", kCustomModel);
  write(dir.path() / "one" / "data" / "delay.cdf", "0 0\n10 1\n");
  const std::optional<ir::System> system = load(dir.path() / "one" / "delays.bip");
  ASSERT_TRUE(system);
  const ir::ExternSources sources = ir::extern_sources_of(*system, {});
  ASSERT_EQ(sources.size(), 1u);  // two ports, one file
  EXPECT_EQ(sources[0].name, "cdf/delay.cdf");
  EXPECT_EQ(sources[0].contents, "0 0\n10 1\n");
  const std::string hash = ir::model_hash(*system, sources);

  // Elsewhere, the same files: the same model.
  write(dir.path() / "two" / "delays.bip", kCustomModel);
  write(dir.path() / "two" / "data" / "delay.cdf", "0 0\n10 1\n");
  const std::optional<ir::System> moved = load(dir.path() / "two" / "delays.bip");
  ASSERT_TRUE(moved);
  EXPECT_EQ(ir::model_hash(*moved, ir::extern_sources_of(*moved, {})), hash);

  // Other dates: another model.
  write(dir.path() / "two" / "data" / "delay.cdf", "0 0\n20 1\n");
  EXPECT_NE(ir::model_hash(*moved, ir::extern_sources_of(*moved, {})), hash);

  fs::remove(dir.path() / "two" / "data" / "delay.cdf");
  EXPECT_THROW(ir::extern_sources_of(*moved, {}), ir::ExternSourceError);
}

}  // namespace
}  // namespace smcbip::bipc
