// The ASN.1 data view of a TASTE design: the subset of X.680 that TASTE data views use, read
// with located diagnostics, its references resolved and each type mapped to BIP data.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "bipc/diagnostics.h"

namespace smcbip::taste2bip::asn1 {

enum class TypeKind : std::uint8_t {
  Integer,
  Real,
  Boolean,
  Null,
  Enumerated,
  Sequence,
  SequenceOf,
  Choice,
  OctetString,
  BitString,
  CharacterString,  // IA5String, NumericString, PrintableString, VisibleString, UTF8String
  Reference,        // a type named by another assignment, optionally `Module.Type`
};

/// What a type becomes in BIP: a scalar (INTEGER and ENUMERATED are `int`, BOOLEAN `bool`, REAL
/// `float`) or an extern type for everything structured.
enum class BipData : std::uint8_t { Unknown, Int, Bool, Float, Extern };

/// A value in a constraint or an argument of a parameterized type.
struct Value {
  enum class Kind : std::uint8_t { Integer, Real, Min, Max, Name } kind = Kind::Integer;
  std::int64_t integer = 0;  // Integer; also a Name once resolved to an integer value
  double real = 0;           // Real (and Integer, converted)
  std::string text;          // as written (`-1.0`, `MAX`, `numT-String`)
  /// A Name after resolve: whether it names a value (`integer`/`real` then hold it) or a
  /// parameter of the enclosing parameterized assignment.
  bool resolved = false;
  bool is_parameter = false;
  bool is_integer = false;  // a Name resolved to an integer value
  bipc::Location at;
};

/// `lower..upper`; a single value has lower and upper equal.
struct Range {
  Value lower, upper;
};

/// A constraint: the union (`|`) of its ranges; no ranges means no constraint.
struct Constraint {
  std::vector<Range> ranges;
  bool extensible = false;  // `(0..10, ...)`
  bipc::Location at;
  bool empty() const { return ranges.empty(); }
};

struct Enumerant {
  std::string name;
  std::int64_t value = 0;  // as written, or numbered as X.680 19.3 does for unnumbered ones
  bool explicit_value = false;
  bipc::Location at;
};

struct Component;

/// Identifies a type assignment of a DataView: `modules[module].types[index]`.
struct TypeId {
  std::size_t module = 0;
  std::size_t index = 0;
  friend bool operator==(const TypeId&, const TypeId&) = default;
};

struct Type {
  TypeKind kind = TypeKind::Integer;
  Constraint range;                   // value constraint: INTEGER, REAL, or a reference to one
  Constraint size;                    // SIZE: SEQUENCE OF, strings
  std::vector<Enumerant> enumerants;  // ENUMERATED
  std::vector<Component> components;  // SEQUENCE, CHOICE (alternatives)
  bool extensible = false;            // `...` in ENUMERATED, SEQUENCE or CHOICE
  std::unique_ptr<Type> element;      // SEQUENCE OF
  std::string string_kind;            // CharacterString: `IA5String`, ...
  // Reference: `module.name{arguments}`; `module` empty when not written.
  std::string module;
  std::string name;
  std::vector<Value> arguments;
  // Set by resolve.
  std::optional<TypeId> target;  // Reference: the assignment named
  BipData bip = BipData::Unknown;
  bipc::Location at;
};

struct Component {
  std::string name;
  Type type;
  bool optional = false;
  std::string default_value;  // DEFAULT value as written; empty when none
  bipc::Location at;
};

/// A value parameter of a parameterized type assignment: `{Governor: name}`.
struct Parameter {
  std::string governor;
  std::string name;
  bipc::Location at;
};

struct TypeAssignment {
  std::string name;
  std::vector<Parameter> parameters;  // `T-StringP{T-UInt32: max} ::= ...`
  Type type;
  bipc::Location at;
};

struct ValueAssignment {
  std::string name;
  Type type;
  std::string value;  // value notation as written: `60`, `{ hello, world }`
  bipc::Location at;
};

/// `a, b FROM M`.
struct Import {
  std::string module;
  std::vector<std::string> names;
  std::vector<bipc::Location> name_at;
  bipc::Location at;  // the module name
};

struct Module {
  std::string name;
  std::string tag_default;  // `AUTOMATIC`, `EXPLICIT`, `IMPLICIT` or empty
  bool exports_all = true;  // no EXPORTS clause, or `EXPORTS ALL`
  std::vector<Import> imports;
  std::vector<TypeAssignment> types;
  std::vector<ValueAssignment> values;
  bipc::Location at;
};

/// The modules of one design, from several files.
struct DataView {
  std::vector<Module> modules;

  /// The module named `name`, or null.
  const Module* module(std::string_view name) const;
  /// The type `name` as seen from module `in_module`: its own assignment or the one it imports
  /// (following chains of IMPORTS). With `in_module` empty, the first module defining `name`.
  std::optional<TypeId> find_type(std::string_view name, std::string_view in_module = {}) const;
  const TypeAssignment* type(TypeId id) const;
  /// The value assignment `name` as seen from `in_module`, like find_type.
  const ValueAssignment* find_value(std::string_view name, std::string_view in_module = {}) const;
};

/// Reads the modules of `text` (registered as `file` in the caller's SourceFiles) and appends
/// them to `into`. Every problem is a located error in `diags`; reading stops after 20 errors.
void read_asn1(const std::string& text, std::uint32_t file, DataView& into,
               bipc::Diagnostics& diags);

/// Resolves every reference of `view` (types, IMPORTS, value names in constraints), reports
/// unknown names, bad imports and types defined in terms of themselves, and sets each Type's
/// `bip`. Run it once all files are read; reading more afterwards needs another resolve. Its
/// errors share the reader's budget of 20 per file.
void resolve(DataView& view, bipc::Diagnostics& diags);

/// The BIP data that a type maps to, following references (Unknown before resolve).
BipData bip_data(const DataView& view, const Type& type);

/// The integer a bound stands for after resolve: its number, the integer value it names, or,
/// for a parameter of a parameterized assignment, the matching argument of `instance` (a
/// Reference to that assignment, e.g. `T-String ::= T-StringP{numT-String}`). Nullopt for
/// MIN, MAX, reals and what cannot be resolved.
std::optional<std::int64_t> bound_integer(const DataView& view, const Value& bound,
                                          const Type* instance = nullptr);

}  // namespace smcbip::taste2bip::asn1
