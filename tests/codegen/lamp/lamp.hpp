// The lamp's extern C++ (lamp.bip).
#pragma once

int brighter(int level);
