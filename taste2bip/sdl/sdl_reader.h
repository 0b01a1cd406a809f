// Reads SDL-PR text (OpenGEODE's textual SDL) into the syntax tree of sdl_ast.h.
#pragma once

#include <cstdint>
#include <string>

#include "bipc/diagnostics.h"
#include "taste2bip/sdl/sdl_ast.h"

namespace smcbip::taste2bip::sdl {

/// Reads the SDL-PR `text` (registered as `file` in the caller's SourceFiles). Keywords are
/// case-insensitive, names keep their spelling, comments (`/* CIF ... */`, `-- ...`) are skipped.
/// Problems are located errors in `diags` (at most about twenty per file); never throws.
/// Returns what was read.
SdlFile read_sdl(const std::string& text, std::uint32_t file, bipc::Diagnostics& diags);

}  // namespace smcbip::taste2bip::sdl
