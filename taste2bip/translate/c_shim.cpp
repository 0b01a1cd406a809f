#include "taste2bip/translate/detail/c_shim.h"

#include <cctype>

#include "taste2bip/translate/c_types.h"

namespace smcbip::taste2bip::detail {

namespace {

std::string lower_case(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

std::string cpp_type(const std::string& bip_type) {
  if (bip_type == "float") return "double";
  if (bip_type == "string") return "std::string";
  return bip_type;  // int, bool
}

/// The C++ expression of type `bip_type` reading the C piece `c`.
std::string read_piece(const std::string& c, const std::string& bip_type) {
  if (bip_type == "string") return "std::string(" + c + ", strnlen(" + c + ", sizeof " + c + "))";
  return "static_cast<" + cpp_type(bip_type) + ">(" + c + ")";
}

/// The C++ statement setting the C piece `c` to the BIP value `v`.
std::string write_piece(const std::string& c, const std::string& bip_type, const std::string& v) {
  if (bip_type == "string") {
    return "std::snprintf(" + c + ", sizeof " + c + ", \"%s\", " + v + ".c_str());";
  }
  return c + " = static_cast<std::remove_reference_t<decltype(" + c + ")>>(" + v + ");";
}

/// The shim's variable of parameter `p` of interface `i`: a buffer for a provided interface's
/// parameter, a pointer to the caller's for a required one.
std::string buffer(const FunctionSignature& f, const SignalInterface& i, const SignalParameter& p) {
  return f.name + "__" + i.data_of(p);
}

std::string activation(const FunctionSignature& f) { return f.name + "__activation"; }

/// The leaf's C piece, after `value` (an lvalue of the parameter's C type).
std::string piece(const asn1::DataView& data, const SignalParameter& p, const Leaf& leaf,
                  const std::string& value) {
  const auto id = find_type_spelled(data, p.asn1_type);
  const asn1::TypeAssignment* a = id ? data.type(*id) : nullptr;
  const std::optional<std::string> path = a ? c_access(data, a->type, leaf) : std::nullopt;
  return value + path.value_or("");
}

void add_call(FunctionShim& shim, std::string name, std::string result,
              std::vector<std::string> params, const std::string& arguments, std::string body) {
  const std::string returns = result.empty() ? "void" : cpp_type(result);
  std::string definition = returns + " " + name + "(" + arguments + ") {\n" + body + "}\n\n";
  shim.calls.push_back({std::move(name), std::move(result), std::move(params), definition});
}

void provided_interface(const FunctionSignature& f, const SignalInterface& p,
                        const asn1::DataView& data, FunctionShim& shim) {
  const std::string run = f.name + "__run_" + p.name;
  std::string arguments, body, c_arguments, params_text;
  std::vector<std::string> params;
  for (const SignalParameter& param : p.parameters) {
    const std::string b = buffer(f, p, param);
    shim.state += "thread_local " + c_parameter_type(data, param.asn1_type) + " " + b + ";\n";
    c_arguments += (c_arguments.empty() ? "&" : ", &") + b;
    body += "  std::memset(&" + b + ", 0, sizeof " + b + ");\n";
    for (const Leaf& leaf : param.leaves) {
      const std::string name = leaf_name(p.data_of(param), leaf);
      if (param.out) {
        add_call(shim, shim_get(f, name), leaf.type, {}, "",
                 "  return " + read_piece(piece(data, param, leaf, b), leaf.type) + ";\n");
        continue;
      }
      const std::string v = "a" + std::to_string(params.size());
      params.push_back(leaf.type);
      arguments += (arguments.empty() ? "" : ", ") + cpp_type(leaf.type) + " " + v;
      body += "  " + write_piece(piece(data, param, leaf, b), leaf.type, v) + "\n";
    }
  }
  shim.state += "void " + run + "() { " + c_function_name(f) + "_PI_" + c_interface_name(p) + "(" +
                c_arguments + "); }\n\n";
  body += "  return " + activation(f) + ".start(&" + run + ");\n";
  add_call(shim, shim_call(f, p), "int", std::move(params), arguments, body);
}

void required_interface(const FunctionSignature& f, const SignalInterface& r, std::size_t number,
                        const asn1::DataView& data, FunctionShim& shim) {
  std::string c_params, keep;
  for (const SignalParameter& param : r.parameters) {
    const std::string b = buffer(f, r, param), type = c_parameter_type(data, param.asn1_type);
    const std::string pointer = param.out ? type + "*" : "const " + type + "*";
    shim.state += "thread_local " + pointer + " " + b + " = nullptr;\n";
    const std::string c_name = (param.out ? "OUT_" : "IN_") + c_identifier(param.name);
    c_params += (c_params.empty() ? "" : ", ") + pointer + " " + c_name;
    keep += "  " + b + " = " + c_name + ";\n";
    for (const Leaf& leaf : param.leaves) {
      const std::string name = leaf_name(r.data_of(param), leaf);
      const std::string c = piece(data, param, leaf, "(*" + b + ")");
      if (param.out) {
        add_call(shim, shim_set(f, name), "", {leaf.type}, cpp_type(leaf.type) + " v",
                 "  if (" + b + " != nullptr) " + write_piece(c, leaf.type, "v") + "\n");
      } else {
        add_call(shim, shim_get(f, name), leaf.type, {}, "",
                 "  return " + b + " != nullptr ? " + read_piece(c, leaf.type) + " : " +
                     cpp_type(leaf.type) + "{};\n");
      }
    }
  }
  shim.required_entries += "extern \"C\" void " + c_function_name(f) + "_RI_" +
                           c_interface_name(r) + "(" + (c_params.empty() ? "void" : c_params) +
                           ") {\n" + keep + "  " + activation(f) + ".pause(" +
                           std::to_string(number) + ");\n}\n\n";
}

/// Timer `t` (the k-th): `<f>_RI_SET_<t>` and `<f>_RI_RESET_<t>` pause the body with status
/// codes after the required interfaces' (timer_status), and its expiry calls `<f>_PI_<t>`.
void timer(const FunctionSignature& f, std::size_t k, FunctionShim& shim) {
  const std::string& t = f.context_timers[k];
  const std::string c = c_function_name(f), run = f.name + "__run_timer_" + t;
  shim.state += "void " + run + "() { " + c + "_PI_" + c_identifier(t) + "(); }\n\n";
  shim.required_entries += "extern \"C\" void " + c + "_RI_SET_" + c_identifier(t) +
                           "(const asn1SccT_UInt32* val) {\n  " + f.name +
                           "__timer_value = static_cast<int>(*val);\n  " + activation(f) +
                           ".pause(" + std::to_string(timer_status(f, k, true)) + ");\n}\n\n";
  shim.required_entries += "extern \"C\" void " + c + "_RI_RESET_" + c_identifier(t) +
                           "(void) {\n  " + activation(f) + ".pause(" +
                           std::to_string(timer_status(f, k, false)) + ");\n}\n\n";
  add_call(shim, shim_call_timer(f, t), "int", {}, "",
           "  return " + activation(f) + ".start(&" + run + ");\n");
}

/// `<f>_ctxt` set to the view's values: single numbers and booleans (others stay zero).
std::string context_values(const FunctionSignature& f) {
  std::string text;
  const std::string ctxt = c_function_name(f) + "_ctxt";
  text += "  std::memset(&" + ctxt + ", 0, sizeof " + ctxt + ");\n";
  for (const ContextValue& c : f.context) {
    const std::string v = lower_case(c.value);
    const bool number = !v.empty() && v.find_first_not_of("+-.0123456789e") == std::string::npos;
    if (c.leaves.size() == 1 && c.leaves[0].suffix.empty() &&
        (number || v == "true" || v == "false")) {
      text += "  " + ctxt + "." + c_context_field(c) + " = " + v + ";\n";
    }
  }
  return text;
}

}  // namespace

std::string shim_startup(const FunctionSignature& f) { return f.name + "_bip_startup"; }
std::string shim_call(const FunctionSignature& f, const SignalInterface& provided) {
  return f.name + "_bip_call_" + provided.name;
}
std::string shim_resume(const FunctionSignature& f) { return f.name + "_bip_resume"; }
std::string shim_call_timer(const FunctionSignature& f, const std::string& timer) {
  return f.name + "_bip_expire_" + timer;
}
std::string shim_timer_value(const FunctionSignature& f) { return f.name + "_bip_timer_value"; }
int timer_status(const FunctionSignature& f, std::size_t k, bool set) {
  return static_cast<int>(f.required.size() + 2 * k) + (set ? 1 : 2);
}
std::string shim_get(const FunctionSignature& f, const std::string& data) {
  return f.name + "_bip_get_" + data;
}
std::string shim_set(const FunctionSignature& f, const std::string& data) {
  return f.name + "_bip_set_" + data;
}

std::string bip_declaration(const ShimCall& call) {
  std::string params;
  for (const std::string& p : call.params) params += (params.empty() ? "" : ", ") + p;
  return "extern function " + (call.result.empty() ? "" : call.result + " ") + call.name + "(" +
         params + ")";
}

std::string c_function_name(const FunctionSignature& f) {
  return lower_case(c_identifier(f.source->name));
}

std::string c_context_field(const ContextValue& c) {
  return lower_case(c_identifier(c.name));
}

std::string c_interface_name(const SignalInterface& i) { return c_identifier(i.source->name); }

std::string c_parameter_type(const asn1::DataView& data, const std::string& asn1_type) {
  const auto id = find_type_spelled(data, asn1_type);
  const asn1::TypeAssignment* a = id ? data.type(*id) : nullptr;
  return c_type_name(a ? a->name : asn1_type);
}

FunctionShim function_shim(const FunctionSignature& f, const asn1::DataView& data) {
  FunctionShim shim;
  shim.state = "thread_local Activation " + activation(f) + ";\n";
  const std::string ctxt = c_function_name(f) + "_ctxt";
  std::string startup = "  claim_bodies();\n  " + activation(f) + ".reset();\n";
  if (!f.context.empty()) {
    shim.context = "context_" + c_function_name(f) + " " + ctxt + ";\n";
    startup += context_values(f);
  }
  startup += "  " + c_function_name(f) + "_startup();\n";
  add_call(shim, shim_startup(f), "", {}, "", startup);
  for (const SignalInterface& p : f.provided) provided_interface(f, p, data, shim);
  for (std::size_t k = 0; k < f.required.size(); ++k) {
    required_interface(f, f.required[k], k + 1, data, shim);
  }
  if (!f.context_timers.empty()) {
    shim.state += "thread_local int " + f.name + "__timer_value = 0;\n";
    add_call(shim, shim_timer_value(f), "int", {}, "", "  return " + f.name + "__timer_value;\n");
  }
  for (std::size_t k = 0; k < f.context_timers.size(); ++k) timer(f, k, shim);
  add_call(shim, shim_resume(f), "int", {}, "", "  return " + activation(f) + ".resume();\n");
  return shim;
}

}  // namespace smcbip::taste2bip::detail
