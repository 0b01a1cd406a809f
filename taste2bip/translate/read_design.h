// A TASTE design read from its files as the taste2bip tool is given them: the interface view
// (AADL or XML, told apart by their text), the data view's ASN.1 files, the SDL of the SDL
// functions and the atom types the user wrote for other functions.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "bipc/diagnostics.h"
#include "taste2bip/translate/package.h"

namespace smcbip::taste2bip {

struct DesignFiles {
  std::string interface_view;
  /// The ASN.1 files; none: every `.asn` file in the interface view's folder and below. The
  /// module TASTE-BasicTypes is supplied when no file defines it.
  std::vector<std::string> data_views;
  /// Folders searched (with their subfolders) for `<function>.pr`, the name's case ignored; none:
  /// the interface view's folder.
  std::vector<std::string> sdl_folders;
  /// Folders searched (with their subfolders) for the bodies of C and C++ functions,
  /// `<function>.c` (C) or `<function>.cc` / `.cpp` (CPP), the name's case ignored; none: the
  /// interface view's folder.
  std::vector<std::string> source_folders;
  /// Function name -> a file holding its atom type (Design::behaviours).
  std::map<std::string, std::string> behaviours;
};

/// Reads the design. Files are registered in `files` (the Design points at it) and every
/// problem is a located error in `diags` (nullopt when there is one); what was assumed (files
/// found by default, the built-in module) is appended to `notes`.
std::optional<Design> read_design(const DesignFiles& paths, bipc::SourceFiles& files,
                                  bipc::Diagnostics& diags, std::vector<std::string>& notes);

}  // namespace smcbip::taste2bip
