#include "taste2bip/translate/detail/faulty_package.h"

#include <algorithm>
#include <sstream>

namespace smcbip::taste2bip::detail {

namespace {

std::string first_word(const std::string& line) {
  std::istringstream in(line);
  std::string word;
  in >> word;
  return word;
}

/// The declarations of a nominal atom (its lines are written one declaration each), renamed,
/// with an initial transition to its first place and no other.
std::string replica(const AtomType& atom) {
  std::istringstream in(atom.text);
  std::string line, out, first_place;
  while (std::getline(in, line)) {
    const std::string word = first_word(line);
    if (word == "atom") {
      out += "  atom type " + atom.name + "_faulty()\n";
    } else if (word == "data" || word == "clock" || word == "port" || word == "place" ||
               word == "export" || word.rfind("@", 0) == 0) {
      out += line + "\n";
      if (word == "place" && first_place.empty()) {
        std::istringstream names(line.substr(line.find("place") + 5));
        std::getline(names, first_place, ',');
        first_place = first_word(first_place);
      }
    }
  }
  out += "    initial to " + first_place + "\n";
  out += "    // the faulty behaviour: transitions marked @fault\n  end\n";
  return out;
}

}  // namespace

std::string faulty_package(const std::string& name, const std::string& declarations,
                           const std::vector<AtomType>& atoms,
                           const std::vector<AtomType>& faulty) {
  std::string text =
      "// The faulty package of the FDIR workflow, written by taste2bip: each\n"
      "// function's atom with its interface, data and places, to be given its\n"
      "// faulty behaviour.\n";
  text += "package " + name + "_faulty\n" + declarations;
  for (const AtomType& atom : atoms) {
    const auto given = std::find_if(faulty.begin(), faulty.end(), [&](const AtomType& a) {
      return a.name == atom.name + "_faulty";
    });
    text += given != faulty.end() ? given->text : replica(atom);
  }
  return text + "end\n";
}

std::string requirements_package(const std::string& name) {
  return "// The requirements package of the FDIR workflow, written by taste2bip: the observers "
         "of\n"
         "// the requirements, as BIP atoms synchronised with the nominal and faulty ones.\n"
         "package " +
         name + "_requirements\nend\n";
}

}  // namespace smcbip::taste2bip::detail
