// The consumer's one operation, shared by its program and its module.
#pragma once

/// Runs `smcbip simulate`'s command line (without the subcommand) over the installed libraries:
/// parses the model, simulates it once, prints the trace on stdout; returns the run code.
int simulate_model(int argc, const char* const* argv);
