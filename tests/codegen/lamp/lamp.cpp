// The lamp's extern C++ (lamp.bip).
#include "lamp.hpp"

int brighter(int level) { return 3 * level + 1; }

// Latin-1 bytes, as a C++ library may well return.
std::string name_of(int level) {
  return level < 100 ? "d\xE9"
                       "but"
                     : "pleine";
}
