// The error fdir reports for a model or property it cannot prove anything about yet.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>

#include "bipc/diagnostics.h"

namespace smcbip::fdir {

/// A construct of the model or property that the prover does not handle; `at` is its position
/// in the model's sources (or in the property file when `in_property`), when known.
class UnsupportedModel : public std::runtime_error {
 public:
  explicit UnsupportedModel(const std::string& message,
                            std::optional<bipc::Location> at = std::nullopt,
                            bool in_property = false)
      : std::runtime_error(message), at(at), in_property(in_property) {}
  std::optional<bipc::Location> at;
  bool in_property = false;
};

}  // namespace smcbip::fdir
