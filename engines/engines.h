// The engines' public interface, whole: every header of engines/api. Programs that run models
// (the tools, generated projects, host programs) include this or the engines/api headers they
// need; the rest of engines/ (semantics, interpreter, stochastic, ...) is the implementation.
#pragma once

#include "engines/api/code_ops.h"
#include "engines/api/compiled_model.h"
#include "engines/api/execution.h"
#include "engines/api/externs.h"
#include "engines/api/model.h"
#include "engines/api/options.h"
#include "engines/api/plugin.h"
#include "engines/api/replay.h"
#include "engines/api/run_observer.h"
#include "engines/api/simulate.h"
#include "engines/api/time_value.h"
#include "engines/api/value.h"
