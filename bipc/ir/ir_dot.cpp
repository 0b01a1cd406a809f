// Draws the instance tree with Graphviz and renders it by running the `dot` program.
#include "bipc/ir/ir_dot.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "bipc/output_file.h"

extern char** environ;

namespace smcbip::bipc::ir {

namespace {

/// Escapes text for a double-quoted Graphviz string.
std::string escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out;
}

/// A double-quoted Graphviz string of `lines`, one per line.
std::string dot_string(const std::vector<std::string>& lines) {
  std::string out = "\"";
  for (std::size_t i = 0; i < lines.size(); ++i) out += (i > 0 ? "\\n" : "") + escaped(lines[i]);
  return out + "\"";
}

/// Escapes the characters that structure a record label (then quoted without escaping again).
std::string record_text(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (std::strchr("{}|<>\"\\ ", c) != nullptr) out += '\\';
    out += c;
  }
  return out;
}

std::string base_name(const std::string& path, const std::string& root) {
  if (path.empty()) return root;
  return last_component(path);
}

/// Port parameters quoted as triggers in a connector type's define.
void collect_triggers(const std::vector<DefineNode>& nodes, std::vector<bool>& triggers) {
  for (const DefineNode& node : nodes) {
    if (node.port != kNone && node.port < triggers.size()) triggers[node.port] = node.trigger;
    collect_triggers(node.children, triggers);
  }
}

class DotWriter {
 public:
  explicit DotWriter(const System& system) : s_(system) {}

  std::string run() {
    // Top to bottom: components in a row, the connectors that join them below (as BIP
    // pictures are drawn), connectors bound hierarchically further down.
    out_ += "digraph " + dot_string({s_.root_type}) + " {\n";
    out_ += "  graph [fontname=\"Helvetica\", fontsize=11];\n";
    out_ += "  node [fontname=\"Helvetica\", fontsize=10];\n";
    out_ += "  edge [dir=none, color=\"#404040\"];\n";
    if (!s_.compounds.empty()) compound(0, "  ");
    for (Index k = 0; k < s_.connectors.size(); ++k) edges(k);
    out_ += "}\n";
    return out_;
  }

 private:
  // Children are listed by the compound, so the walk follows the tree, one level per cluster.
  void compound(Index c, const std::string& indent) {
    const CompoundInstance& node = s_.compounds[c];
    out_ += indent + "subgraph cluster_c" + std::to_string(c) + " {\n";
    const std::string inner = indent + "  ";
    const std::string label =
        base_name(node.path, s_.root_name) + " : " + last_component(node.type);
    out_ += inner + "label=" + dot_string({label}) + "; style=rounded; color=\"#7090c0\";\n";
    for (Index a : node.atoms) atom(a, inner);
    for (Index k : node.connectors) connector(k, inner);
    for (Index child : node.compounds) {
      if (child < s_.compounds.size() && child != c) compound(child, inner);
    }
    out_ += indent + "}\n";
  }

  void atom(Index a, const std::string& indent) {
    if (a >= s_.atoms.size() || s_.atoms[a].type >= s_.atom_types.size()) return;
    const AtomInstance& instance = s_.atoms[a];
    const AtomType& type = s_.atom_types[instance.type];
    std::string fields;
    for (std::size_t p = 0; p < type.ports.size(); ++p) {
      if (!type.ports[p].exported) continue;
      if (!fields.empty()) fields += '|';
      fields += "<p" + std::to_string(p) + "> " + record_text(type.ports[p].name);
    }
    // Name and type above, one field per exported port below, where the connectors attach.
    std::string label = record_text(base_name(instance.path, s_.root_name)) + "\\n" +
                        record_text(last_component(type.name));
    if (!fields.empty()) label = "{" + label + "|{" + fields + "}}";
    out_ += indent + "a" + std::to_string(a) +
            " [shape=record, style=filled, fillcolor=\"#f4f4e8\", label=\"" + label + "\"];\n";
  }

  void connector(Index k, const std::string& indent) {
    if (k >= s_.connectors.size()) return;
    const ConnectorInstance& instance = s_.connectors[k];
    const bool typed = instance.type < s_.connector_types.size();
    const std::string type = typed ? last_component(s_.connector_types[instance.type].name) : "?";
    const bool exports = typed && s_.connector_types[instance.type].export_name.has_value();
    out_ += indent + "k" + std::to_string(k) + " [shape=ellipse, fontsize=9, margin=0.02, " +
            (exports ? "peripheries=2, " : "") +
            "label=" + dot_string({base_name(instance.path, s_.root_name), type}) + "];\n";
  }

  void edges(Index k) {
    const ConnectorInstance& instance = s_.connectors[k];
    std::vector<bool> triggers(instance.bound.size(), false);
    if (instance.type < s_.connector_types.size()) {
      collect_triggers(s_.connector_types[instance.type].define, triggers);
    }
    // The first port's edge leads into the connector and the others out of it, so that the
    // layers alternate as data flows (sender, connector, receivers) instead of one wide row of
    // components over one row of connectors. Sub-connectors always sit above their binder.
    for (std::size_t i = 0; i < instance.bound.size(); ++i) {
      for (const PortRef& ref : instance.bound[i]) {
        std::string attrs = triggers[i] ? "style=dashed" : "";
        const std::string self = "k" + std::to_string(k);
        std::string edge;
        if (ref.kind == PortRef::Kind::Connector) {
          edge = "k" + std::to_string(ref.instance) + " -> " + self;
          attrs += std::string(attrs.empty() ? "" : ", ") + "penwidth=2, dir=forward";
        } else {
          const std::string port =
              "a" + std::to_string(ref.instance) + ":p" + std::to_string(ref.port);
          edge = i == 0 ? port + " -> " + self : self + " -> " + port;
        }
        out_ += "  " + edge + (attrs.empty() ? ";\n" : " [" + attrs + "];\n");
      }
    }
  }

  const System& s_;
  std::string out_;
};

/// Runs `dot -T<format> -o <output> <input>`; collects what it says on stderr.
bool run_dot(const std::string& format, const std::string& input, const std::string& output,
             std::string& error) {
  int pipe_fds[2];
  if (::pipe(pipe_fds) != 0) {
    error = std::string("cannot create a pipe: ") + std::strerror(errno);
    return false;
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addclose(&actions, pipe_fds[0]);
  posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], STDERR_FILENO);
  posix_spawn_file_actions_addclose(&actions, pipe_fds[1]);
  const std::string type_option = "-T" + format;
  std::vector<std::string> args = {"dot", type_option, "-o", output, input};
  std::vector<char*> argv;
  for (std::string& arg : args) argv.push_back(arg.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int spawn_error = ::posix_spawnp(&pid, "dot", &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(pipe_fds[1]);
  if (spawn_error != 0) {
    ::close(pipe_fds[0]);
    error = spawn_error == ENOENT
                ? "the Graphviz program 'dot' was not found on the PATH; install graphviz, or "
                  "write a .dot file instead"
                : std::string("cannot run 'dot': ") + std::strerror(spawn_error);
    return false;
  }
  // Read stderr to the end before waiting, so that a talkative dot cannot block on the pipe.
  std::string messages;
  char buffer[4096];
  ssize_t n = 0;
  while ((n = ::read(pipe_fds[0], buffer, sizeof buffer)) != 0) {
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) break;
    if (messages.size() < 4096) messages.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(pipe_fds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return true;
  while (!messages.empty() && std::isspace(static_cast<unsigned char>(messages.back()))) {
    messages.pop_back();
  }
  error = "'dot' failed" + (messages.empty() ? std::string() : ": " + messages);
  return false;
}

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

}  // namespace

std::string to_dot(const System& system) { return DotWriter(system).run(); }

bool render_svg(const std::string& dot, const std::string& out_path, std::string& error) {
  const std::string ext = lower_extension(out_path);
  const bool text = ext == ".dot" || ext == ".gv";
  if (!text && ext != ".svg" && ext != ".png" && ext != ".pdf") {
    error = "cannot tell the picture format of '" + out_path +
            "': use .svg, .png, .pdf, or .dot for Graphviz text";
    return false;
  }
  // Temporaries sit next to the result, so that the final rename stays on one file system.
  const std::string pattern = out_path + ".tmpXXXXXX";
  std::string result;
  if (text) {
    result = write_temporary_file(pattern, dot);
  } else {
    const std::string input = write_temporary_file(pattern, dot);
    result = input.empty() ? std::string() : write_temporary_file(pattern, "");
    const bool ok = !result.empty() && run_dot(ext.substr(1), input, result, error);
    if (!input.empty()) ::unlink(input.c_str());
    if (!ok) {
      if (!result.empty()) ::unlink(result.c_str());
      if (error.empty()) error = "cannot write next to '" + out_path + "': " + std::strerror(errno);
      return false;
    }
  }
  if (result.empty()) {
    error = "cannot write next to '" + out_path + "': " + std::strerror(errno);
    return false;
  }
  if (std::rename(result.c_str(), out_path.c_str()) != 0) {
    error = "cannot write '" + out_path + "': " + std::strerror(errno);
    ::unlink(result.c_str());
    return false;
  }
  return true;
}

}  // namespace smcbip::bipc::ir
