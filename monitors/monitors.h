// The monitors library: the property language (parsing, normalised text) and
// the online monitor that judges runs against it.
#pragma once

#include "monitors/online/critical_bound.h"
#include "monitors/online/extremum.h"
#include "monitors/online/horizon.h"
#include "monitors/online/online_monitor.h"
#include "monitors/online/operator_monitor.h"
#include "monitors/parse/property_parser.h"
#include "monitors/property/ast.h"
#include "monitors/resolve/resolve_names.h"
#include "monitors/run/run_monitor.h"
#include "monitors/trace/trace_check.h"
