// The lamp's extern C++ (lamp.bip).
#include "lamp.hpp"

int brighter(int level) { return 3 * level + 1; }
