// The data view as the C types that TASTE's C and C++ function bodies are written against,
// named as the ASN.1 compiler of the TASTE toolchain (asn1scc) names them: `asn1Scc` and the
// assignment's name with '-' as '_'; INTEGER `asn1SccSint` (`asn1SccUint` when its range
// starts at 0 or above), REAL `asn1Real`, BOOLEAN `flag`; SEQUENCE a struct with an `exist`
// bit-field for OPTIONAL fields; CHOICE a struct of `kind` (`<alt>_PRESENT`, 1 for the first
// alternative) and union `u`; SEQUENCE OF and OCTET/BIT STRING `arr` with `nCount` when their
// size varies; character strings `char[max + 1]`; ENUMERATED a C enum of the ASN.1 values,
// each enumerant named `<C type>_<enumerant>` (`asn1SccMySeq_validity_invalid`). A `_PRESENT`
// name that two CHOICE types share is prefixed with the type's name.
// Anonymous inner types are named after their place (`asn1SccT_field`, `asn1SccT_elm`).
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "taste2bip/asn1/data_view.h"
#include "taste2bip/translate/bip_types.h"

namespace smcbip::taste2bip {

/// `name` with every character C does not allow in an identifier as '_'.
std::string c_identifier(std::string_view name);

/// The C type of the assignment named `assignment_name`: `asn1SccT_SEQUENCE`.
std::string c_type_name(std::string_view assignment_name);

/// The text of `dataview-uniq.h`: every type assignment of `view` as a C typedef, the types it
/// uses first. An assignment without a C form (a parameterized one, a SEQUENCE OF or string
/// without a SIZE bound) is a comment saying so.
std::string c_dataview_header(const asn1::DataView& view);

/// The C expression, after a value of `type`, that reaches the piece `leaf` of leaves_of(type)
/// holds: `.x`, `.u.left.arr[2]`, `.kind` (CHOICE `present`), `.nCount` (`length`),
/// `.exist.f` (`f_exist`); empty for the value itself. Nullopt when the path does not fit.
std::optional<std::string> c_access(const asn1::DataView& view, const asn1::Type& type,
                                    const Leaf& leaf);

}  // namespace smcbip::taste2bip
