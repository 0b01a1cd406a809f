// Internal to the console: which field options each telecommand subtype takes.
#pragma once

#include "console/tc_options.h"

namespace smcbip::pus::console::detail {

/// Throws TcSyntaxError for a field option the subtype does not take (naming the option) and
/// for a required one that is missing (--function of [8,1], --rate of [9,1]).
void check_fields(const MessageType& type, const TcWords& words);

}  // namespace smcbip::pus::console::detail
