// Hashes a model's IR bytes and extern sources (layout in model_hash.h), and finds its sources.
#include "bipc/ir/model_hash.h"

#include <array>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "bipc/ir/detail/sha256.h"
#include "bipc/ir/ir_data.h"

namespace smcbip::bipc::ir {

namespace fs = std::filesystem;

namespace {

void update_length(detail::Sha256& sha, std::uint64_t n) {
  std::array<std::uint8_t, 8> bytes{};
  for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<std::uint8_t>(n >> (8 * i));
  sha.update(bytes);
}

bool is_file(const fs::path& path) {
  std::error_code error;
  return fs::is_regular_file(path, error);
}

/// The whole file at `path`; throws ExternSourceError naming it as `name`.
std::string read_source(const fs::path& path, const std::string& name) {
  if (!is_file(path)) throw ExternSourceError{name, "no such file: " + path.string()};
  std::ifstream in(path, std::ios::binary);
  std::ostringstream contents;
  if (in) contents << in.rdbuf();
  if (!in || in.bad()) {
    throw ExternSourceError{name, "cannot read " + path.string() + ": " + std::strerror(errno)};
  }
  return contents.str();
}

/// Where an Instr's array holds its site (ir_data.h): a source location too.
constexpr std::size_t kInstrSite = 6;

/// Every source location under `data` set to null, every empirical CDF file named by its file
/// name alone (see model_hash.h).
void drop_locations(nlohmann::json& data) {
  if (data.is_array()) {
    for (nlohmann::json& item : data) drop_locations(item);
    return;
  }
  if (!data.is_object()) return;
  for (auto& [key, value] : data.items()) {
    if (key == "loc") {
      value = nullptr;
    } else if (key == "instrs") {
      for (nlohmann::json& instr : value) instr.erase(kInstrSite);
    } else if (key == "custom_file" && value.is_string()) {
      value = fs::path(value.get<std::string>()).filename().string();
    } else {
      drop_locations(value);
    }
  }
}

std::vector<std::uint8_t> normalised_bytes(const System& system) {
  nlohmann::json data = to_data(system);
  drop_locations(data);
  for (nlohmann::json& source : data["cpp_sources"]) {
    source = fs::path(source.get<std::string>()).filename().string();
  }
  data["cpp_include_dirs"] = nlohmann::json::array();
  data.erase("sites");
  data.erase("source_files");
  return nlohmann::json::to_cbor(data);
}

}  // namespace

std::string model_hash(const System& system, const ExternSources& extern_sources) {
  detail::Sha256 sha;
  sha.update(normalised_bytes(system));
  for (const ExternSource& source : extern_sources) {
    update_length(sha, source.name.size());
    sha.update(source.name);
    update_length(sha, source.contents.size());
    sha.update(source.contents);
  }
  return sha.hex_digest();
}

ExternSources extern_sources_of(const System& system, const std::vector<std::string>& search_dirs) {
  ExternSources sources;
  for (const std::string& source : system.cpp_sources) {
    sources.push_back({fs::path(source).filename().string(), source, read_source(source, source)});
  }
  for (const std::string& header : system.cpp_includes) {
    if (fs::path(header).is_absolute()) {
      sources.push_back({header, header, read_source(header, header)});
      continue;
    }
    std::vector<std::string> dirs = system.cpp_include_dirs;
    dirs.insert(dirs.end(), search_dirs.begin(), search_dirs.end());
    for (const std::string& dir : dirs) {
      const fs::path candidate = fs::path(dir) / header;
      if (is_file(candidate)) {
        sources.push_back({header, candidate.string(), read_source(candidate, header)});
        break;
      }
    }
  }
  std::set<std::string> cdfs;
  for (const AtomType& type : system.atom_types) {
    for (const Port& port : type.ports) {
      if (!port.stochastic || port.stochastic->custom_file.empty()) continue;
      const std::string& file = port.stochastic->custom_file;
      if (!cdfs.insert(file).second) continue;
      sources.push_back(
          {"cdf/" + fs::path(file).filename().string(), file, read_source(file, file)});
    }
  }
  return sources;
}

}  // namespace smcbip::bipc::ir
