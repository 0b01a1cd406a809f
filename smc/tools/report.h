// What `smcbip check` and `smcbip explore` print and write: a table for people, one JSON
// object, CSV rows for spreadsheets.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "monitors/monitors.h"
#include "smc/check/check.h"

namespace smcbip::tools {

/// What the results were computed with, as the command line gave it: enough to reproduce them.
struct Settings {
  std::string method = "auto", undecided = "error";
  const smc::CheckOptions* options = nullptr;  // seed, alpha, beta, delta, confidence, steps
  std::vector<std::string> parameters;         // --param
};

/// The results of one property file on one model.
struct Report {
  const monitors::PropertyFile& file;
  const std::vector<smc::QueryResult>& results;
  std::string model, root, hash;  // the model's file, root and ir::model_hash
  Settings settings;
};

/// `v` with at most `digits` significant digits, as people read numbers in reports.
std::string number_text(double v, int digits = 6);

/// A query's text without its parameters' values.
std::string query_text(const Report& report, const smc::QueryResult& r);
/// The values of a result's parameters, ` t=10 k=2`, or nothing.
std::string parameters_text(const smc::QueryResult& r);

/// Each result on its own lines (check).
void print_results(std::ostream& out, const Report& report);
/// Each query, with what its sweep's guarantee is, then a row per point (explore).
void print_sweeps(std::ostream& out, const Report& report);
/// `{"model": {...}, "settings": {...}, "results": [...]}`, results in file order.
std::string json_text(const Report& report);
/// A header, then a row per result; a column per parameter of the file.
std::string csv_text(const Report& report);

}  // namespace smcbip::tools
