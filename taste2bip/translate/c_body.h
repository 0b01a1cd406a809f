// Functions whose behaviour is a C or C++ body (TASTE's `<function>.c`, `.cc` or `.cpp`): their
// atom calls the body through extern functions that `bipc gen` compiles in, with the body and
// a shim written beside the package.
//
// The shim (`<package>_bodies.cpp`) gives the body what TASTE's glue gives it: the data view's
// C types (`dataview-uniq.h`), `<function>.h` declaring `<function>_startup`,
// `<function>_PI_<p>` and `<function>_RI_<r>`, and `Context-<function>.h` with the context
// parameters. A call of a provided interface runs the body on a stack of its own; when the
// body calls a required interface, the shim hands control back to the model, whose atom makes
// the call as its ports `r_out` (and, for a synchronous one, `r_result`) and then resumes the
// body. So the calls a body makes, in order and with their data, are steps of the model, and
// synchronous calls return what the callee computed. The model runs compiled only (`bipc gen`,
// `smcbip simulate|check --compiled`): the interpreter has no C.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "bipc/diagnostics.h"
#include "taste2bip/asn1/data_view.h"
#include "taste2bip/translate/package.h"
#include "taste2bip/translate/sdl_atom.h"
#include "taste2bip/translate/signature.h"

namespace smcbip::taste2bip {

/// The atom of `function`, whose body is given. Interfaces the shim cannot pass (a parameter
/// without a scalar form, such as an OCTET STRING) and timers are located errors.
std::optional<AtomType> c_body_atom(const FunctionSignature& function, const asn1::DataView& data,
                                    bipc::Diagnostics& diags);

/// What a package with bodies needs beside it: the files, and the `@cpp(...)` annotation
/// that names them for `bipc gen`.
struct BodyFiles {
  std::vector<OutputFile> files;
  std::string annotation;  // with its newline; empty when no function has a body
};

/// The files of `functions` (each with its body) in package `package`. Call it for atoms
/// c_body_atom made without errors.
BodyFiles c_body_files(
    const std::string& package,
    const std::vector<std::pair<const FunctionSignature*, const FunctionBody*>>& functions,
    const asn1::DataView& data);

}  // namespace smcbip::taste2bip
