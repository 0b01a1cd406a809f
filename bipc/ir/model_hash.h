// The identity of a model: SHA-256 over its IR's bytes and its extern C++ sources.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "bipc/errors.h"
#include "bipc/ir/ir.h"

namespace smcbip::bipc::ir {

/// One extern C++ file of a model.
struct ExternSource {
  std::string name;      // what the hash covers: a source's file name, a header as written
  std::string path;      // where it was read
  std::string contents;  // its bytes
};
using ExternSources = std::vector<ExternSource>;

/// The lowercase hex SHA-256 (64 digits) of these bytes, in this order:
///
///   to_cbor(normalised(to_data(system)))  the IR as CBOR (ir_data.h), not length-prefixed
///   for each source in extern_sources, in the order given:
///     u64le(name.size())      name bytes
///     u64le(contents.size())  contents bytes
///
/// where u64le(n) is n as 8 bytes, least significant first, and normalised() drops what only
/// says where the model is stored or written: every source location ("loc") becomes null,
/// instructions lose their site and the system its `sites` and `source_files`,
/// `cpp_sources` and empirical CDF files (`custom_file`) keep their file names alone and
/// `cpp_include_dirs` is emptied. So a model
/// keeps its hash when its files move or gain comments, and changes it with anything that
/// changes what it does or the bytes of its extern code. The CBOR is one data item with
/// definite lengths, so it ends where its own header says; every later field is
/// length-prefixed, so no two different inputs give the same byte string (moving a byte from
/// one name or file into the next changes a length). Sources' paths are not hashed.
std::string model_hash(const System& system, const ExternSources& extern_sources);

/// An extern source named by the model that cannot be read: the user's input error.
struct ExternSourceError : InputError {
  ExternSourceError(std::string path_named, std::string why)
      : InputError("extern source " + path_named + ": " + why),
        path(std::move(path_named)),
        message(std::move(why)) {}
  std::string path;     // as the model names it
  std::string message;  // e.g. "no such file"
};

/// The extern C++ files of `system`, read from disk, for model_hash. In this order:
///  - each of `cpp_sources` (`@cpp(src=...)`), read from the path the IR holds (the front end
///    has already resolved a relative name against the folder of the package naming it, so a
///    relative path here is relative to the current directory, as it was for the front end)
///    and named by its file name;
///  - each of `cpp_includes` (`@cpp(include=...)`), named as written, read from the first of
///    `cpp_include_dirs` (the naming packages' folders), then of `search_dirs` (the -I folders,
///    as the front end searches packages), that holds it; an absolute name is read as is.
///    A relative header found in none of them is taken for a header of the C++ toolchain
///    (`stdio.h`, `unistd.h`) and left out: it is no part of the model;
///  - each empirical CDF file of a `custom` stochastic port (once, in the order of the atom
///    types and their ports), read from the path the IR holds and named `cdf/` + its file
///    name: the dates it gives are part of what the model does.
/// Throws ExternSourceError for a source file, or an absolute header, that is missing or
/// unreadable.
ExternSources extern_sources_of(const System& system, const std::vector<std::string>& search_dirs);

}  // namespace smcbip::bipc::ir
