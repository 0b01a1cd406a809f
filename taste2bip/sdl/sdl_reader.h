// Reads SDL-PR text (OpenGEODE's textual SDL) into the syntax tree of sdl_ast.h.
#pragma once

#include <cstdint>
#include <string>

#include "bipc/diagnostics.h"
#include "taste2bip/sdl/sdl_ast.h"

namespace smcbip::taste2bip::sdl {

/// Reads the SDL-PR `text` (registered as `file` in the caller's SourceFiles). Keywords are
/// case-insensitive, names keep their spelling, comments (`/* CIF ... */`, `-- ...`) are skipped.
/// Problems are located errors in `diags` (at most twenty per file, then a note), each saying
/// what was expected; nesting deeper than 200 levels stops reading with one error. Never throws.
/// Returns what was read.
///
/// The grammar is OpenGEODE's (sdl92.g) for systems, blocks, channels, signal routes, processes,
/// procedures, text areas, states with substructures, transitions and expressions, plus the SDL
/// forms `process type`, `process P : T` and `save`. SDL constructs outside it (newtype,
/// syntype, synonym, create, export, alternative, macros, services, ...) are errors naming the
/// construct.
SdlFile read_sdl(const std::string& text, std::uint32_t file, bipc::Diagnostics& diags);

}  // namespace smcbip::taste2bip::sdl
