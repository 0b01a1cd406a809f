// Flattens nested functions: the leaves remain, and calls are followed through the parents'
// delegations (child RI -> parent RI, parent PI -> child PI) to the leaf that runs them.
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <vector>

#include "taste2bip/interface_view/interface_view.h"

namespace smcbip::taste2bip {
namespace {

std::string where(const bipc::Location& at) {
  return std::to_string(at.line) + ":" + std::to_string(at.column);
}

/// One interface of one function: the nodes of the delegation graph.
struct Port {
  std::size_t function = 0;
  bool provided = false;
  std::size_t interface = 0;
  auto operator<=>(const Port&) const = default;
};

/// A hop of the graph: where a connection leads and which connection it is.
struct Hop {
  Port to;
  std::size_t connection = 0;
};

class Flattener {
 public:
  Flattener(const InterfaceView& view, bipc::Diagnostics& diags) : view_(view), diags_(diags) {}

  InterfaceView run() {
    index_functions();
    for (std::size_t c = 0; c < view_.connections.size(); ++c) add_connection(c);

    InterfaceView flat;
    flat.assumptions = view_.assumptions;
    std::vector<std::size_t> leaves;
    for (std::size_t f = 0; f < view_.functions.size(); ++f) {
      if (has_children_[f]) continue;
      leaves.push_back(f);
      Function leaf = view_.functions[f];
      leaf.parent.reset();
      flat.functions.push_back(std::move(leaf));
    }
    for (std::size_t f : leaves) {
      for (std::size_t r = 0; r < view_.functions[f].required.size(); ++r) {
        follow({f, false, r}, flat.connections);
      }
    }
    return flat;
  }

 private:
  void index_functions() {
    has_children_.assign(view_.functions.size(), false);
    for (std::size_t f = 0; f < view_.functions.size(); ++f) {
      const Function& function = view_.functions[f];
      if (function.parent && *function.parent < view_.functions.size()) {
        has_children_[*function.parent] = true;
      }
      auto [it, fresh] = by_name_.emplace(function.name, f);
      if (!fresh) {
        diags_.error(function.at, "function `" + function.name + "` is declared twice (first at " +
                                      where(view_.functions[it->second].at) +
                                      "): expected unique function names");
      }
    }
  }

  /// The port an endpoint names, or an error at the connection.
  std::optional<Port> resolve(const Endpoint& end, const Connection& connection) {
    const auto it = by_name_.find(end.function);
    if (it == by_name_.end()) {
      diags_.error(connection.at, "connection names function `" + end.function +
                                      "`: expected the name of a function of the view");
      return std::nullopt;
    }
    const Function& function = view_.functions[it->second];
    const std::vector<Interface>& list = end.provided ? function.provided : function.required;
    for (std::size_t i = 0; i < list.size(); ++i) {
      if (list[i].name == end.interface) return Port{it->second, end.provided, i};
    }
    diags_.error(connection.at, std::string("connection names ") +
                                    (end.provided ? "provided" : "required") + " interface `" +
                                    end.function + "." + end.interface + "`: expected one of " +
                                    end.function + "'s " +
                                    (end.provided ? "provided" : "required") + " interfaces");
    return std::nullopt;
  }

  bool is_parent(std::size_t parent, std::size_t child) const {
    return view_.functions[child].parent == parent;
  }

  /// Adds the connection as a directed hop: call RI -> PI, delegation in parent PI -> child PI,
  /// delegation out child RI -> parent RI, whichever way the file wrote the endpoints.
  void add_connection(std::size_t c) {
    const Connection& connection = view_.connections[c];
    std::optional<Port> from = resolve(connection.from, connection);
    std::optional<Port> to = resolve(connection.to, connection);
    if (!from || !to) return;
    if (from->provided && !to->provided) std::swap(from, to);
    if (from->provided == to->provided) {
      const bool provided = from->provided;
      if (is_parent(to->function, from->function) == provided) std::swap(from, to);
      const bool ok = provided ? is_parent(from->function, to->function)
                               : is_parent(to->function, from->function);
      if (!ok) {
        diags_.error(connection.at,
                     std::string("connection joins two ") + (provided ? "provided" : "required") +
                         " interfaces: expected a function's and one of its children's (" +
                         (provided ? "a parent PI delegated to a child PI"
                                   : "a child RI delegated to a parent RI") +
                         ")");
        return;
      }
    }
    hops_[*from].push_back({*to, c});
  }

  const Interface& interface_of(const Port& port) const {
    const Function& function = view_.functions[port.function];
    return port.provided ? function.provided[port.interface] : function.required[port.interface];
  }

  std::string name_of(const Port& port) const {
    return view_.functions[port.function].name + "." + interface_of(port).name;
  }

  /// Follows a leaf's required interface to every leaf provided interface it reaches.
  void follow(const Port& start, std::vector<Connection>& out) {
    const auto first = hops_.find(start);
    if (first == hops_.end()) return;  // not connected: not a flattening matter
    std::set<Port> seen{start};
    std::set<Port> reached;
    // The connection leaving the leaf locates the flat connection it becomes.
    for (const Hop& hop : first->second) {
      std::vector<Hop> stack{hop};
      while (!stack.empty()) {
        const Hop current = stack.back();
        stack.pop_back();
        if (!seen.insert(current.to).second) continue;  // a cycle or a shared chain
        const Port& port = current.to;
        if (port.provided && !has_children_[port.function]) {
          if (reached.insert(port).second) {
            out.push_back({{view_.functions[start.function].name, interface_of(start).name, false},
                           {view_.functions[port.function].name, interface_of(port).name, true},
                           view_.connections[hop.connection].at});
          }
          continue;
        }
        const auto next = hops_.find(port);
        if (next == hops_.end()) {
          dangling(port, current.connection);
          continue;
        }
        for (const Hop& onward : next->second) stack.push_back(onward);
      }
    }
  }

  void dangling(const Port& port, std::size_t connection) {
    if (!reported_.insert(connection).second) return;
    const std::string& function = view_.functions[port.function].name;
    if (port.provided) {
      diags_.error(view_.connections[connection].at,
                   "connection reaches `" + name_of(port) + "`, which " + function +
                       " delegates to none of its functions: expected a connection from it to "
                       "a child's provided interface");
    } else {
      diags_.error(view_.connections[connection].at,
                   "connection delegates to `" + name_of(port) +
                       "`, which is connected to nothing: expected a connection from it to a "
                       "provided interface");
    }
  }

  const InterfaceView& view_;
  bipc::Diagnostics& diags_;
  std::vector<bool> has_children_;
  std::unordered_map<std::string, std::size_t> by_name_;
  std::map<Port, std::vector<Hop>> hops_;
  std::set<std::size_t> reported_;
};

}  // namespace

InterfaceView flatten(const InterfaceView& view, bipc::Diagnostics& diags) {
  return Flattener(view, diags).run();
}

}  // namespace smcbip::taste2bip
