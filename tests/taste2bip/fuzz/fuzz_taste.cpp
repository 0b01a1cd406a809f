#include "fuzz_taste.h"

#include <cstdlib>
#include <iostream>
#include <string>

#include "taste2bip/asn1/data_view.h"
#include "taste2bip/interface_view/interface_view.h"
#include "taste2bip/sdl/sdl_reader.h"

namespace smcbip::taste2bip::fuzz {

namespace {

/// More errors than any reader may give for one file (each stops at 20, then notes the rest),
/// with the resolution's or the flattening's of the same view.
constexpr std::size_t kMostDiagnostics = 100;

[[noreturn]] void fail(const std::string& why) {
  std::cerr << "taste2bip fuzz: " << why << "\n";
  std::abort();
}

/// Line and column of every diagnostic lie within the text (the end of the text counts).
void check_locations(const bipc::Diagnostics& diags, const std::string& text) {
  std::size_t lines = 1;
  for (char c : text) lines += c == '\n' ? 1 : 0;
  if (diags.all().size() > kMostDiagnostics) {
    fail(std::to_string(diags.all().size()) + " diagnostics for one file");
  }
  for (const bipc::Diagnostic& d : diags.all()) {
    if (d.location.line < 1 || d.location.column < 1 || d.location.line > lines ||
        d.location.column > text.size() + 1) {
      fail("diagnostic at " + std::to_string(d.location.line) + ":" +
           std::to_string(d.location.column) + " outside the text: " + d.message);
    }
  }
}

}  // namespace

bool reader_named(std::string_view name, Reader& out) {
  if (name == "asn1")
    out = Reader::Asn1;
  else if (name == "aadl")
    out = Reader::Aadl;
  else if (name == "xml")
    out = Reader::Xml;
  else if (name == "sdl")
    out = Reader::Sdl;
  else if (name == "sdlatom")
    out = Reader::SdlAtom;
  else
    return false;
  return true;
}

void run_reader_on(Reader reader, const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  bipc::Diagnostics diags;
  switch (reader) {
    case Reader::Asn1: {
      asn1::DataView view;
      asn1::read_asn1(text, 0, view, diags);
      asn1::resolve(view, diags);
      break;
    }
    case Reader::Aadl:
      (void)flatten(read_aadl_interface_view(text, 0, diags), diags);
      break;
    case Reader::Xml:
      (void)flatten(read_xml_interface_view(text, 0, diags), diags);
      break;
    case Reader::Sdl:
      (void)sdl::read_sdl(text, 0, diags);
      break;
    case Reader::SdlAtom:
      return translate_sdl_on(text);
  }
  check_locations(diags, text);
}

}  // namespace smcbip::taste2bip::fuzz
