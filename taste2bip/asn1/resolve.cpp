// Resolution of a data view: names to assignments, IMPORTS checked, self-defined types found,
// and every type mapped to BIP data.
#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <map>
#include <set>

#include "taste2bip/asn1/data_view.h"
#include "taste2bip/asn1/lookup.h"

namespace smcbip::taste2bip::asn1 {
namespace {

constexpr int kMaxValueHops = 32;
constexpr std::size_t kMaxErrorsPerFile = 20;

std::string line_of(const bipc::Location& at) { return "line " + std::to_string(at.line); }

/// A reference of one assignment to another that needs no indirection to be finite.
struct Edge {
  std::size_t to = 0;  // global index of the assignment
  bipc::Location at;
};

class Resolver {
 public:
  Resolver(DataView& view, bipc::Diagnostics& diags) : view_(view), diags_(diags), lookup_(view) {
    for (const Module& m : view_.modules) {
      first_.push_back(count_);
      count_ += m.types.size();
    }
    // The reader's errors count against the same budget per file.
    for (const bipc::Diagnostic& d : diags.all()) {
      if (d.severity == bipc::Severity::Error) ++errors_per_file_[d.location.file];
    }
    for (auto& [file, count] : errors_per_file_) {
      if (count >= kMaxErrorsPerFile) count = kMaxErrorsPerFile + 1;  // already noted
    }
  }

  void run() {
    check_names();
    for (std::size_t m = 0; m < view_.modules.size(); ++m) {
      check_imports(m);
      Module& module = view_.modules[m];
      for (TypeAssignment& a : module.types) resolve_type(a.type, m, a.parameters);
      for (ValueAssignment& v : module.values) resolve_type(v.type, m, {});
    }
    find_cycles();
    map_assignments();
    for (Module& module : view_.modules) {
      for (TypeAssignment& a : module.types) set_bip(a.type);
      for (ValueAssignment& v : module.values) set_bip(v.type);
    }
  }

 private:
  /// Reports an error, at most kMaxErrorsPerFile per file with the reader's (then one note).
  void error(bipc::Location at, std::string message) {
    std::size_t& count = errors_per_file_[at.file];
    if (count > kMaxErrorsPerFile) return;
    if (++count > kMaxErrorsPerFile) {
      diags_.note(at, "too many errors in this file: the others are not reported");
      return;
    }
    diags_.error(at, std::move(message));
  }

  void check_names() {
    std::map<std::string, bipc::Location> modules;
    for (const Module& m : view_.modules) {
      auto [it, fresh] = modules.emplace(m.name, m.at);
      if (!fresh) {
        error(m.at, "the module '" + m.name + "' is already defined (" + line_of(it->second) + ")");
      }
      std::map<std::string, bipc::Location> names;
      for (const TypeAssignment& a : m.types) {
        auto [at, fresh_name] = names.emplace(a.name, a.at);
        if (!fresh_name) {
          error(a.at, "the type '" + a.name + "' is already defined in module '" + m.name + "' (" +
                          line_of(at->second) + ")");
        }
      }
      for (const ValueAssignment& v : m.values) {
        auto [at, fresh_name] = names.emplace(v.name, v.at);
        if (!fresh_name) {
          error(v.at, "the value '" + v.name + "' is already defined in module '" + m.name + "' (" +
                          line_of(at->second) + ")");
        }
      }
    }
  }

  void check_imports(std::size_t m) {
    for (const Import& import : view_.modules[m].imports) {
      auto from = lookup_.module(import.module);
      if (!from) {
        error(import.at, "unknown module '" + import.module + "' in IMPORTS");
        continue;
      }
      for (std::size_t i = 0; i < import.names.size(); ++i) {
        const std::string& name = import.names[i];
        if (!lookup_.type(*from, name) && !lookup_.value(*from, name)) {
          error(import.name_at[i],
                "module '" + import.module + "' has no type or value '" + name + "' to import");
        }
      }
    }
  }

  /// Whether module m imports `name` (an unresolved import is reported at the import).
  bool imported(std::size_t m, const std::string& name) const {
    for (const Import& import : view_.modules[m].imports) {
      for (const std::string& n : import.names) {
        if (n == name) return true;
      }
    }
    return false;
  }

  void resolve_type(Type& t, std::size_t m, const std::vector<Parameter>& params) {
    for (Range& r : t.range.ranges) {
      resolve_value(r.lower, m, params);
      resolve_value(r.upper, m, params);
    }
    for (Range& r : t.size.ranges) {
      resolve_value(r.lower, m, params);
      resolve_value(r.upper, m, params);
    }
    if (t.kind == TypeKind::Reference) resolve_reference(t, m, params);
    for (Component& c : t.components) resolve_type(c.type, m, params);
    if (t.element) resolve_type(*t.element, m, params);
  }

  void resolve_reference(Type& t, std::size_t m, const std::vector<Parameter>& params) {
    std::string shown = t.module.empty() ? t.name : t.module + "." + t.name;
    if (!t.module.empty()) {
      auto index = lookup_.module(t.module);
      if (!index) {
        error(t.at, "unknown module '" + t.module + "' in '" + shown + "'");
        return;
      }
      t.target = lookup_.type(*index, t.name);
    } else {
      t.target = lookup_.type(m, t.name);
    }
    if (!t.target) {
      if (t.module.empty() && imported(m, t.name)) return;
      error(t.at, "unknown type '" + shown + "'");
      return;
    }
    for (Value& v : t.arguments) resolve_value(v, m, params);
    const TypeAssignment* target = view_.type(*t.target);
    if (target->parameters.size() != t.arguments.size()) {
      error(t.at, "'" + shown + "' takes " + std::to_string(target->parameters.size()) +
                      " argument(s), but " + std::to_string(t.arguments.size()) + " are given");
    }
  }

  void resolve_value(Value& v, std::size_t m, const std::vector<Parameter>& params) {
    if (v.kind != Value::Kind::Name) return;
    for (const Parameter& p : params) {
      if (p.name == v.text) {
        v.is_parameter = true;
        v.resolved = true;
        return;
      }
    }
    auto id = lookup_.value(m, v.text);
    if (!id) {
      if (!imported(m, v.text)) error(v.at, "unknown value '" + v.text + "'");
      return;
    }
    // A value may name another value: follow the names to a number.
    for (int hop = 0; hop < kMaxValueHops && id; ++hop) {
      const std::string& text = view_.modules[id->module].values[id->index].value;
      if (parse_number(text, v)) {
        v.resolved = true;
        return;
      }
      id = lookup_.value(id->module, text);
    }
    error(v.at, "the value '" + v.text + "' is not a number");
  }

  static bool parse_number(const std::string& text, Value& v) {
    std::int64_t integer = 0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), integer);
    if (ec == std::errc() && end == text.data() + text.size()) {
      v.is_integer = true;
      v.integer = integer;
      v.real = static_cast<double>(integer);
      return true;
    }
    if (text.empty() || !(text[0] == '-' || (text[0] >= '0' && text[0] <= '9'))) return false;
    char* real_end = nullptr;
    double real = std::strtod(text.c_str(), &real_end);
    if (real_end != text.c_str() + text.size()) return false;
    v.real = real;
    return true;
  }

  // --- cycles: A ::= B, B ::= A, or A ::= SEQUENCE { a A } -----------------------------------
  void collect_edges(const Type& t, std::vector<Edge>& edges) const {
    if (t.kind == TypeKind::Reference && t.target) {
      edges.push_back(Edge{first_[t.target->module] + t.target->index, t.at});
    }
    // A CHOICE, a SEQUENCE OF and an OPTIONAL component make finite values possible.
    if (t.kind == TypeKind::Sequence) {
      for (const Component& c : t.components) {
        if (!c.optional) collect_edges(c.type, edges);
      }
    }
  }

  void find_cycles() {
    std::vector<std::vector<Edge>> edges(count_);
    std::vector<const TypeAssignment*> node(count_);
    for (std::size_t m = 0; m < view_.modules.size(); ++m) {
      for (std::size_t i = 0; i < view_.modules[m].types.size(); ++i) {
        node[first_[m] + i] = &view_.modules[m].types[i];
        collect_edges(view_.modules[m].types[i].type, edges[first_[m] + i]);
      }
    }
    enum class Color : std::uint8_t { White, Grey, Black };
    std::vector<Color> color(count_, Color::White);
    struct Frame {
      std::size_t node;
      std::size_t next_edge;
    };
    // Iterative depth-first search: a long chain of references must not exhaust the stack.
    for (std::size_t root = 0; root < count_; ++root) {
      if (color[root] != Color::White) continue;
      std::vector<Frame> stack{{root, 0}};
      color[root] = Color::Grey;
      while (!stack.empty()) {
        Frame& top = stack.back();
        if (top.next_edge == edges[top.node].size()) {
          color[top.node] = Color::Black;
          stack.pop_back();
          continue;
        }
        const Edge& e = edges[top.node][top.next_edge++];
        if (color[e.to] == Color::White) {
          color[e.to] = Color::Grey;
          stack.push_back({e.to, 0});
        } else if (color[e.to] == Color::Grey) {
          std::string path;
          bool on = false;
          for (const Frame& f : stack) {
            on = on || f.node == e.to;
            if (on) path += node[f.node]->name + " -> ";
          }
          path += node[e.to]->name;
          error(e.at, "the type '" + node[e.to]->name + "' is defined in terms of itself (" + path +
                          ") without SEQUENCE OF, CHOICE or OPTIONAL between");
        }
      }
    }
  }

  /// The BIP data of every assignment: a chain of references is followed once, and every
  /// assignment on it gets the answer (linear in the number of assignments).
  void map_assignments() {
    assignment_bip_.assign(count_, BipData::Unknown);
    std::vector<bool> done(count_, false);
    for (std::size_t start = 0; start < count_; ++start) {
      std::vector<std::size_t> chain;
      std::size_t g = start;
      BipData result = BipData::Unknown;
      while (true) {
        if (done[g]) {
          result = assignment_bip_[g];
          break;
        }
        done[g] = true;  // a chain that comes back here is a cycle: it stays Unknown
        chain.push_back(g);
        const Type& t = node_type(g);
        if (t.kind != TypeKind::Reference) {
          result = detail::bip_of_kind(t.kind);
          break;
        }
        if (!t.target) break;
        g = first_[t.target->module] + t.target->index;
      }
      for (std::size_t n : chain) assignment_bip_[n] = result;
    }
  }

  const Type& node_type(std::size_t g) const {
    std::size_t m = static_cast<std::size_t>(std::upper_bound(first_.begin(), first_.end(), g) -
                                             first_.begin() - 1);
    // Modules without types share a first index: take the last one that has g.
    while (first_[m] + view_.modules[m].types.size() <= g) ++m;
    return view_.modules[m].types[g - first_[m]].type;
  }

  void set_bip(Type& t) {
    if (t.kind == TypeKind::Reference) {
      t.bip =
          t.target ? assignment_bip_[first_[t.target->module] + t.target->index] : BipData::Unknown;
    } else {
      t.bip = detail::bip_of_kind(t.kind);
    }
    for (Component& c : t.components) set_bip(c.type);
    if (t.element) set_bip(*t.element);
  }

  DataView& view_;
  bipc::Diagnostics& diags_;
  std::vector<std::size_t> first_;  // global index of each module's first type assignment
  std::size_t count_ = 0;
  detail::Lookup lookup_;
  std::vector<BipData> assignment_bip_;
  std::map<std::uint32_t, std::size_t> errors_per_file_;
};

}  // namespace

void resolve(DataView& view, bipc::Diagnostics& diags) { Resolver(view, diags).run(); }

}  // namespace smcbip::taste2bip::asn1
