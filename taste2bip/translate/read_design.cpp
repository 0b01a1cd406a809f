#include "taste2bip/translate/read_design.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "bipc/errors.h"
#include "bipc/input_file.h"
#include "taste2bip/asn1/taste_basic_types.h"
#include "taste2bip/sdl/sdl_reader.h"

namespace smcbip::taste2bip {

namespace {

namespace fs = std::filesystem;

/// Design files are text a tool wrote or a person edits: 64 MiB bounds what reading one costs.
constexpr std::uint64_t kMaxDesignFileBytes = std::uint64_t{64} << 20;

std::string lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

/// The regular files under `folder` whose name satisfies `wanted`, sorted (a stable order).
template <typename Wanted>
std::vector<std::string> files_under(const std::string& folder, Wanted wanted) {
  std::vector<std::string> out;
  std::error_code ec;
  fs::recursive_directory_iterator it(folder, fs::directory_options::skip_permission_denied, ec);
  for (; !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
    if (it->is_regular_file(ec) && wanted(it->path())) out.push_back(it->path().string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::string folder_of(const std::string& path) {
  const std::string parent = fs::path(path).parent_path().string();
  return parent.empty() ? "." : parent;
}

bool is_xml(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r\n\xEF\xBB\xBF");
  return first != std::string::npos && text[first] == '<';
}

InterfaceView read_view(const std::string& path, bipc::SourceFiles& files,
                        bipc::Diagnostics& diags) {
  const std::string text = bipc::read_input_file(path, "the interface view", kMaxDesignFileBytes);
  const std::uint32_t file = files.add(path);
  return is_xml(text) ? read_xml_interface_view(text, file, diags)
                      : read_aadl_interface_view(text, file, diags);
}

asn1::DataView read_data(const DesignFiles& paths, bipc::SourceFiles& files,
                         bipc::Diagnostics& diags, std::vector<std::string>& notes) {
  std::vector<std::string> asn = paths.data_views;
  if (asn.empty()) {
    const std::string folder = folder_of(paths.interface_view);
    asn = files_under(folder, [](const fs::path& p) { return p.extension() == ".asn"; });
    notes.push_back("data view: the " + std::to_string(asn.size()) + " .asn files under " + folder);
  }
  asn1::DataView view;
  for (const std::string& path : asn) {
    const std::string text = bipc::read_input_file(path, "the data view", kMaxDesignFileBytes);
    asn1::read_asn1(text, files.add(path), view, diags);
  }
  if (view.module(asn1::kTasteBasicTypesModule) == nullptr) {
    asn1::read_asn1(std::string(asn1::taste_basic_types_text()), files.add("<TASTE-BasicTypes>"),
                    view, diags);
    notes.push_back("data view: TASTE-BasicTypes as the TASTE toolchain supplies it");
  }
  asn1::resolve(view, diags);
  return view;
}

/// The folders given for a kind of file, or the interface view's folder; each must exist.
std::vector<std::string> search_folders(const std::vector<std::string>& given,
                                        const DesignFiles& paths, const std::string& what) {
  std::vector<std::string> folders = given;
  if (folders.empty()) folders.push_back(folder_of(paths.interface_view));
  for (const std::string& folder : folders) {
    std::error_code ec;
    if (!fs::is_directory(folder, ec)) {
      throw InputError("the " + what + " folder " + folder + " is not a folder", {folder, 0, 0});
    }
  }
  return folders;
}

/// The SDL of the design's SDL functions: `<function>.pr` in the folders.
std::vector<sdl::SdlFile> read_sdl(const DesignFiles& paths, const InterfaceView& view,
                                   bipc::SourceFiles& files, bipc::Diagnostics& diags) {
  const std::vector<std::string> folders = search_folders(paths.sdl_folders, paths, "SDL");
  std::vector<sdl::SdlFile> out;
  for (const Function& f : view.functions) {
    if (lower(f.language) != "sdl") continue;
    const std::string wanted = lower(f.name) + ".pr";
    for (const std::string& folder : folders) {
      const auto found = files_under(
          folder, [&](const fs::path& p) { return lower(p.filename().string()) == wanted; });
      if (found.empty()) continue;
      const std::string text =
          bipc::read_input_file(found.front(), "the SDL file", kMaxDesignFileBytes);
      out.push_back(sdl::read_sdl(text, files.add(found.front()), diags));
      break;
    }
  }
  return out;
}

/// The file names a body of `f` may have, lower case; none for a language without bodies here.
std::vector<std::string> body_names(const Function& f) {
  const std::string language = lower(f.language), name = lower(f.name);
  if (language == "c") return {name + ".c"};
  if (language == "cpp" || language == "c++") return {name + ".cc", name + ".cpp"};
  return {};
}

/// The bodies of the design's C and C++ functions found in the folders (the first match in
/// the folders' order).
std::map<std::string, FunctionBody> read_bodies(const DesignFiles& paths, const InterfaceView& view,
                                                std::vector<std::string>& notes) {
  const std::vector<std::string> folders =
      search_folders(paths.source_folders, paths, "C/C++ source");
  std::map<std::string, FunctionBody> out;
  for (const Function& f : view.functions) {
    const std::vector<std::string> names = body_names(f);
    if (names.empty()) continue;
    for (const std::string& folder : folders) {
      const auto found = files_under(folder, [&](const fs::path& p) {
        const std::string file = lower(p.filename().string());
        return std::find(names.begin(), names.end(), file) != names.end();
      });
      if (found.empty()) continue;
      out[f.name] = {found.front(), bipc::read_input_file(found.front(), "the body of " + f.name,
                                                          kMaxDesignFileBytes)};
      notes.push_back("body of " + f.name + ": " + found.front());
      break;
    }
  }
  return out;
}

}  // namespace

std::optional<Design> read_design(const DesignFiles& paths, bipc::SourceFiles& files,
                                  bipc::Diagnostics& diags, std::vector<std::string>& notes) {
  const std::size_t errors = diags.error_count();
  Design design;
  design.files = &files;
  design.view = read_view(paths.interface_view, files, diags);
  design.data = read_data(paths, files, diags, notes);
  design.sdl = read_sdl(paths, design.view, files, diags);
  design.bodies = read_bodies(paths, design.view, notes);
  for (const auto& [function, path] : paths.behaviours) {
    design.behaviours[function] =
        bipc::read_input_file(path, "the atom type of " + function, kMaxDesignFileBytes);
  }
  if (diags.error_count() > errors) return std::nullopt;
  return design;
}

}  // namespace smcbip::taste2bip
