// The monitors library: the property language (parsing, normalised text) and, in later stages,
// the online monitors that judge runs against it.
#pragma once

#include "monitors/parse/property_parser.h"
#include "monitors/property/ast.h"
#include "monitors/resolve/resolve_names.h"
