// The lamp's extern C++ (lamp.bip).
#pragma once

#include <string>

int brighter(int level);
std::string name_of(int level);
