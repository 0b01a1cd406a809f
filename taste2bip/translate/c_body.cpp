#include "taste2bip/translate/c_body.h"

#include <filesystem>

#include "taste2bip/translate/c_types.h"
#include "taste2bip/translate/detail/c_shim.h"

namespace smcbip::taste2bip {

namespace {

using detail::c_function_name;
using detail::c_interface_name;
using detail::c_parameter_type;

const char* const kBanner = "/* Written by taste2bip. */\n";

// Runs a body's activation on a stack of its own (ucontext), so that the body can stop in the
// middle of a call of a required interface and go on once the model has made that call.
const char* const kActivation =
    R"(// A body's activation, run on a stack of its own: when the body calls a required interface,
// pause() hands control back to the model, which makes the call as BIP interactions and then
// resume()s the body. The stack stays allocated for the thread's next activations.
class Activation {
 public:
  /// Runs `entry` until it returns (0) or calls the k-th required interface (k).
  int start(void (*entry)()) {
    if (!stack_) stack_ = std::make_unique<char[]>(kStackBytes);
    getcontext(&body_);
    body_.uc_stack.ss_sp = stack_.get();
    body_.uc_stack.ss_size = kStackBytes;
    body_.uc_link = &model_;
    entry_ = entry;
    starting_ = this;
    makecontext(&body_, &Activation::run, 0);
    active_ = true;
    return resume();
  }
  /// Goes on after the call the body is paused in; 0 once it has returned.
  int resume() {
    if (!active_) return 0;
    status_ = 0;
    swapcontext(&model_, &body_);
    return status_;
  }
  /// On the body's stack, in a call of the k-th required interface. A call made outside an
  /// activation (from <function>_startup, which TASTE forbids) is dropped.
  void pause(int k) {
    if (!active_) return;
    status_ = k;
    swapcontext(&body_, &model_);
  }
  /// Forgets an activation left paused (a run that ended in it).
  void reset() {
    active_ = false;
    status_ = 0;
  }

 private:
  static constexpr std::size_t kStackBytes = std::size_t{1} << 20;
  static void run() {
    Activation* self = starting_;
    self->entry_();
    self->active_ = false;
    self->status_ = 0;
  }
  static thread_local Activation* starting_;
  ucontext_t body_{}, model_{};
  std::unique_ptr<char[]> stack_;
  void (*entry_)() = nullptr;
  int status_ = 0;
  bool active_ = false;
};

thread_local Activation* Activation::starting_ = nullptr;

// The bodies' own data (their static variables) exist once in the process: runs made on two
// threads at once would share them. The thread that starts a run owns the bodies until it
// ends; a run started on another thread meanwhile is a fault of that run, not a silent mix.
std::atomic<std::thread::id> bodies_owner{};

struct OwnerRelease {
  ~OwnerRelease() {
    std::thread::id me = std::this_thread::get_id();
    bodies_owner.compare_exchange_strong(me, std::thread::id{});
  }
};
thread_local OwnerRelease owner_release;

void claim_bodies() {
  static_cast<void>(&owner_release);  // constructed in this thread, released when it ends
  std::thread::id free{};
  const std::thread::id me = std::this_thread::get_id();
  if (bodies_owner.compare_exchange_strong(free, me) || free == me) return;
  throw smcbip::engines::ExternFault(
      "the functions' C/C++ bodies hold their data once per process, so their runs cannot be "
      "made on several threads at once: run with --threads 1");
}

)";

std::string guard_name(const std::string& file) {
  std::string out = "TASTE2BIP_" + c_identifier(file);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

std::string c_header(const std::string& file, const std::string& what, const std::string& body) {
  const std::string guard = guard_name(file);
  return "/* " + what + " Written by taste2bip. */\n#ifndef " + guard + "\n#define " + guard +
         "\n\n#include \"dataview-uniq.h\"\n\n#ifdef __cplusplus\nextern \"C\" {\n#endif\n\n" +
         body + "\n#ifdef __cplusplus\n}\n#endif\n\n#endif\n";
}

std::string prototype(const std::string& name, const SignalInterface& i,
                      const asn1::DataView& data) {
  std::string params;
  for (const SignalParameter& p : i.parameters) {
    const std::string type = c_parameter_type(data, p.asn1_type);
    params += (params.empty() ? "" : ", ") + (p.out ? type + " *OUT_" : "const " + type + " *IN_") +
              c_identifier(p.name);
  }
  return "void " + name + "(" + (params.empty() ? "void" : params) + ");\n";
}

std::string function_header(const FunctionSignature& f, const asn1::DataView& data) {
  const std::string c = c_function_name(f);
  std::string body = "void " + c + "_startup(void);\n\n";
  for (const SignalInterface& p : f.provided) {
    body += prototype(c + "_PI_" + c_interface_name(p), p, data);
  }
  body += "\n/* Required interfaces: each call is a step of the function's atom. */\n";
  for (const SignalInterface& r : f.required) {
    body += prototype(c + "_RI_" + c_interface_name(r), r, data);
  }
  if (!f.context_timers.empty())
    body += "\n/* Timers: set (ms), reset, and the call at expiry. */\n";
  for (const std::string& t : f.context_timers) {
    const std::string name = c_identifier(t);
    body += "void " + c + "_RI_SET_" + name + "(const asn1SccT_UInt32 *val);\nvoid " + c +
            "_RI_RESET_" + name + "(void);\nvoid " + c + "_PI_" + name + "(void);\n";
  }
  return c_header(c + ".h", "What TASTE's glue declares for the body of " + f.source->name + ".",
                  body);
}

std::string context_file(const FunctionSignature& f) {
  std::string name = c_function_name(f);
  for (char& c : name) c = c == '_' ? '-' : c;
  return "Context-" + name + ".h";
}

std::string context_header(const FunctionSignature& f, const asn1::DataView& data) {
  const std::string c = c_function_name(f);
  std::string body = "typedef struct {\n";
  for (const ContextValue& v : f.context) {
    body += "    " + c_parameter_type(data, v.asn1_type) + " " + detail::c_context_field(v) + ";\n";
  }
  body += "} context_" + c + ";\n\nextern context_" + c + " " + c + "_ctxt;\n";
  return c_header(context_file(f), "The context parameters of " + f.source->name + ".", body);
}

struct ShimText {
  std::string includes, state, definitions, declarations;
};

void add_function(const FunctionSignature& f, const asn1::DataView& data, ShimText& shim,
                  BodyFiles& out, std::string& sources, std::string& headers,
                  const FunctionBody& body) {
  const std::string c = c_function_name(f);
  out.files.push_back({c + ".h", function_header(f, data)});
  shim.includes += "#include \"" + c + ".h\"\n";
  headers += "," + c + ".h";
  if (!f.context.empty()) {
    out.files.push_back({context_file(f), context_header(f, data)});
    shim.includes += "#include \"" + context_file(f) + "\"\n";
    headers += "," + context_file(f);
  }
  const std::string file = std::filesystem::path(body.path).filename().string();
  out.files.push_back({file, body.text});
  sources += "," + file;
  const detail::FunctionShim made = detail::function_shim(f, data);
  shim.state += made.state + "\n";
  shim.definitions += made.context + made.required_entries;
  for (const detail::ShimCall& call : made.calls) {
    shim.definitions += call.definition;
    const std::string proto = call.definition.substr(0, call.definition.find(" {"));
    shim.declarations += proto + ";\n";
  }
}

}  // namespace

BodyFiles c_body_files(
    const std::string& package,
    const std::vector<std::pair<const FunctionSignature*, const FunctionBody*>>& functions,
    const asn1::DataView& data) {
  BodyFiles out;
  if (functions.empty()) return out;
  const std::string shim_name = package + "_bodies";
  std::string sources = shim_name + ".cpp", headers = shim_name + ".h,dataview-uniq.h";
  out.files.push_back({"dataview-uniq.h", c_dataview_header(data)});
  ShimText shim;
  for (const auto& [f, body] : functions)
    add_function(*f, data, shim, out, sources, headers, *body);
  out.files.push_back({shim_name + ".h",
                       std::string("// The extern functions between the atoms and the bodies "
                                   "of the functions.\n") +
                           kBanner + "#pragma once\n\n#include <string>\n\n" + shim.declarations});
  out.files.push_back(
      {shim_name + ".cpp",
       std::string("// The bodies of the design's C/C++ functions, run for their atoms.\n") +
           kBanner + "#include \"" + shim_name +
           ".h\"\n\n#include <ucontext.h>\n\n#include <atomic>\n#include <cstdio>\n"
           "#include <cstring>\n#include <memory>\n#include <string>\n#include <thread>\n"
           "#include <type_traits>\n\n#include \"engines/api/externs.h\"\n#include "
           "\"dataview-uniq.h\"\n" +
           shim.includes + "\nnamespace {\n\n" + kActivation + shim.state + "}  // namespace\n\n" +
           shim.definitions});
  out.annotation = "@cpp(src=\"" + sources + "\", include=\"" + headers + "\")\n";
  return out;
}

}  // namespace smcbip::taste2bip
