// The smc library: the statistics of statistical model checking (hypothesis tests, sampling
// plans, interval estimates).
#pragma once

#include "smc/stats/interval_estimation.h"
#include "smc/stats/sampling_plans.h"
#include "smc/check/check.h"
#include "smc/check/ordered_sampler.h"
#include "smc/stats/sprt.h"
