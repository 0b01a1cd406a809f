// A TASTE interface view: the functions of a design, the interfaces they provide and require with
// their timing, their context parameters, and the connections between them. Both formats (the
// AADL `InterfaceView.aadl` of TASTE 2018 and the XML `interfaceview.xml` of the current editor)
// read into this one model.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "bipc/diagnostics.h"

namespace smcbip::taste2bip {

/// How a provided interface runs (a required interface takes the kind of what it calls).
enum class InterfaceKind : std::uint8_t {
  Cyclic,       // called by its own periodic thread
  Sporadic,     // queued, run by the callee's thread, at most once per MIAT
  Protected,    // run in the caller's thread, mutually exclusive with the function's others
  Unprotected,  // run in the caller's thread
  Any,          // a required interface: whatever the provided one it is connected to is
};

/// A duration in the interface view, in milliseconds.
using Milliseconds = double;

struct Parameter {
  enum class Direction : std::uint8_t { In, Out } direction = Direction::In;
  std::string name;
  /// The ASN.1 type as the view spells it: the XML view writes the ASN.1 name
  /// (`Base-commands-Motion2D`), the AADL view DataView.aadl's (`Base_commands_Motion2D`).
  std::string type;
  bipc::Location at;
};

struct Interface {
  std::string name;  // without TASTE's `PI_`/`RI_` prefix
  InterfaceKind kind = InterfaceKind::Any;
  std::vector<Parameter> parameters;
  std::optional<Milliseconds> period;           // cyclic: period; sporadic: MIAT
  std::optional<Milliseconds> deadline;         //
  std::optional<Milliseconds> dispatch_offset;  // cyclic
  std::optional<std::uint32_t> queue_size;      // sporadic
  std::optional<Milliseconds> wcet_low, wcet_high;
  bipc::Location at;
};

/// A context parameter of a function: a value of an ASN.1 type, or a timer (`type == "Timer"`).
struct ContextParameter {
  std::string name;
  std::string type;
  std::string value;  // as written (ASN.1 value notation); empty for a timer
  bipc::Location at;
};

struct Function {
  std::string name;
  std::string language;  // SDL, C, CPP, Ada, ... as the view spells it; empty when none
  std::vector<Interface> provided, required;
  std::vector<ContextParameter> context;
  /// Nested functions: the index of the enclosing function, or nullopt at the top level.
  std::optional<std::size_t> parent;
  bool is_type = false;  // a function type (XML `is_type="YES"`): not instantiated as such
  bipc::Location at;
};

/// A call path: `from` (a function's required interface) reaches `to` (a provided interface).
/// Inside a parent function, a connection may also join the parent's provided interface to a
/// child's provided one, or a child's required interface to the parent's required one (the
/// delegations that flattening follows).
struct Endpoint {
  std::string function;
  std::string interface;
  bool provided = false;  // the endpoint names a provided interface (else a required one)
};

struct Connection {
  Endpoint from, to;
  bipc::Location at;
};

/// What the reader assumed where the view is silent (TASTE's defaults), for the report.
struct Assumption {
  std::string text;  // e.g. "cyclic interface Ctrl.pulse has no period: 1000 ms"
  bipc::Location at;
};

struct InterfaceView {
  std::vector<Function> functions;
  std::vector<Connection> connections;
  std::vector<Assumption> assumptions;
};

/// Reads the XML interface view of `text` (registered as `file` in the caller's SourceFiles).
/// Errors are located (`file:line:col`) in `diags`; returns what was read.
InterfaceView read_xml_interface_view(const std::string& text, std::uint32_t file,
                                      bipc::Diagnostics& diags);

/// Reads an AADL interface view (TASTE 1.3.x or 2.x generations) as read_xml_interface_view does.
InterfaceView read_aadl_interface_view(const std::string& text, std::uint32_t file,
                                       bipc::Diagnostics& diags);

/// The view with nested functions replaced by their leaf functions: connections through a
/// parent's interfaces are followed to the leaves they delegate to. Unresolvable delegations are
/// errors at the connection.
InterfaceView flatten(const InterfaceView& view, bipc::Diagnostics& diags);

}  // namespace smcbip::taste2bip
