// ASN.1 values as BIP data. The engines hold one machine word per data slot and bind extern C++
// functions over scalars only, so a structured value is spread over scalar BIP data, one per
// leaf (`v` of a SEQUENCE {translation REAL, heading SEQUENCE {rad REAL}} becomes
// `v_translation` and `v_heading_rad`): the interpreter runs it and properties read its fields.
// Only what has no bounded scalar form (OCTET STRING, BIT STRING, SEQUENCE OF longer than
// kMaxElements) stays one extern data of the TASTE C type's name.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "bipc/diagnostics.h"
#include "taste2bip/asn1/data_view.h"

namespace smcbip::taste2bip {

/// The longest SEQUENCE OF spread over scalar data; longer ones stay extern.
inline constexpr std::int64_t kMaxElements = 16;

/// One scalar (or extern) piece of an ASN.1 value.
struct Leaf {
  /// Appended to the variable's name with '_' (empty: the value is one scalar). Field and
  /// alternative names as BIP identifiers, element indices as numbers, plus the bookkeeping
  /// leaves `length` (SEQUENCE OF of variable size), `present` (CHOICE: 1-based index of the
  /// alternative held) and `<field>_exist` (an OPTIONAL field is there).
  std::string suffix;
  /// `int`, `bool`, `float`, `string` or an extern type's name (`asn1SccT_Octets`).
  std::string type;
  /// The ASN.1 type of this piece, references followed (enumerants, ranges); null for the
  /// bookkeeping leaves.
  const asn1::Type* asn1_type = nullptr;
  /// The ASN.1 path to it: field names, alternative names and element indices as written.
  std::vector<std::string> path;
};

/// The variable `name` with `suffix` appended: `v` + `heading_rad` is `v_heading_rad`.
std::string leaf_name(std::string_view name, const Leaf& leaf);

/// A type of the data view as the views and SDL spell it: the XML interface view writes ASN.1's
/// `Base-commands-Motion2D`, AADL `Base_commands_Motion2D`, SDL any case. Matched with '-' and
/// '_' alike and case ignored; nullopt when no type or more than one matches.
std::optional<asn1::TypeId> find_type_spelled(const asn1::DataView& view, std::string_view name);

/// The type `id` names, references followed to a non-reference type (null on a cycle).
const asn1::Type* definition(const asn1::DataView& view, const asn1::Type& type);

/// The leaves of a value of type `type` (resolved), in ASN.1 order.
std::vector<Leaf> leaves_of(const asn1::DataView& view, const asn1::Type& type);

/// The leaves of the type spelled `name` (find_type_spelled), or an error at `at` naming it.
std::optional<std::vector<Leaf>> leaves_of(const asn1::DataView& view, std::string_view name,
                                           const bipc::Location& at, bipc::Diagnostics& diags);

/// The extern type a non-scalar piece of type `type` becomes: TASTE's C name, `asn1Scc` and the
/// assignment's name as a BIP identifier (`asn1SccT_Octets`).
std::string extern_type_name(std::string_view assignment_name);

/// The names of the extern types among `leaves` (each once), to declare in the package.
std::vector<std::string> extern_types_in(const std::vector<Leaf>& leaves);

/// The BIP port type that carries values of these types, in order: `Port` when none, else
/// `Port_` and one letter per type (`i` int, `b` bool, `f` float, `s` string) or the extern
/// type's name between `x` and `_`. Equal type lists share one port type.
std::string port_type_name(const std::vector<std::string>& types);

}  // namespace smcbip::taste2bip
