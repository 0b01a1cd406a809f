// Writes scalable BIP2 models (rendezvous chains and pairs, one big broadcast, busy workers) for
// benchmarks of the front end and the engines.
#include <CLI/CLI.hpp>
#include <cctype>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <ostream>
#include <string>

namespace {

/// Exit codes, as for every smcbip tool: 0 success, 2 usage or input error, 3 internal error.
constexpr int kExitOk = 0;
constexpr int kExitUsage = 2;
constexpr int kExitInternal = 3;

/// True when `name` is a BIP identifier, so that it can serve as a package name.
bool is_identifier(const std::string& name) {
  if (name.empty()) return false;
  const auto first = static_cast<unsigned char>(name.front());
  if (!(std::isalpha(first) || first == '_')) return false;
  for (const char ch : name) {
    const auto c = static_cast<unsigned char>(ch);
    if (!(std::isalnum(c) || c == '_')) return false;
  }
  return true;
}

/// Writes a chain of `atoms` nodes, each neighbour pair joined by a two-port rendezvous that
/// passes the left node's counter to the right node; with `priorities`, each rendezvous is also
/// ranked below the next one, so the compound holds one priority rule per connector.
void write_chain(std::ostream& out, const std::string& package, long atoms, bool priorities) {
  out << "// " << atoms << " atoms in a rendezvous chain.\n"
      << "package " << package << "\n"
      << "  port type Link(int value)\n\n"
      << "  connector type Rdv(Link giver, Link taker)\n"
      << "    define giver taker\n"
      << "    on giver taker provided (giver.value >= 0) down { taker.value = giver.value; }\n"
      << "  end\n\n"
      << "  atom type Node()\n"
      << "    data int count\n"
      << "    export port Link left(count), right(count)\n\n"
      << "    place IDLE, BUSY\n\n"
      << "    initial to IDLE do { count = 0; }\n\n"
      << "    on left from IDLE to BUSY do { count = count + 1; }\n"
      << "    on right from BUSY to IDLE provided (count < 1000000)\n"
      << "    on right from IDLE to IDLE\n"
      << "  end\n\n"
      << "  compound type Top()\n";
  for (long i = 0; i < atoms; ++i) {
    // The chain's ends leave one port each unbound, on purpose: say so, as Verimag's BIP allows.
    if (i == 0 || i + 1 == atoms) out << "    @SuppressWarning(unboundcomponentport)\n";
    out << "    component Node n" << i << "()\n";
  }
  for (long i = 0; i + 1 < atoms; ++i) {
    out << "    connector Rdv c" << i << "(n" << i << ".right, n" << i + 1 << ".left)\n";
  }
  for (long i = 0; priorities && i + 2 < atoms; ++i) {
    out << "    priority p" << i << " c" << i << ":* < c" << i + 1 << ":*\n";
  }
  out << "  end\n"
      << "end\n";
}

/// Writes one sender and `atoms - 1` receivers joined by a single broadcast connector whose
/// type has one port per atom, the sender's being the only trigger.
void write_broadcast(std::ostream& out, const std::string& package, long atoms) {
  const long receivers = atoms - 1;
  out << "// " << atoms << " atoms on one broadcast.\n"
      << "package " << package << "\n"
      << "  port type Sig()\n\n"
      << "  connector type Broadcast(Sig s";
  for (long i = 1; i <= receivers; ++i) out << ", Sig r" << i;
  out << ")\n"
      << "    define s'";
  for (long i = 1; i <= receivers; ++i) out << " r" << i;
  out << "\n"
      << "  end\n\n"
      << "  atom type Sender()\n"
      << "    data int sent\n"
      << "    export port Sig send()\n\n"
      << "    place LIVE\n\n"
      << "    initial to LIVE do { sent = 0; }\n\n"
      << "    on send from LIVE to LIVE do { sent = sent + 1; }\n"
      << "  end\n\n"
      << "  atom type Receiver()\n"
      << "    data int heard\n"
      << "    export port Sig recv()\n\n"
      << "    place LIVE\n\n"
      << "    initial to LIVE do { heard = 0; }\n\n"
      << "    on recv from LIVE to LIVE do { heard = heard + 1; }\n"
      << "  end\n\n"
      << "  compound type Top()\n"
      << "    component Sender sender()\n";
  for (long i = 1; i <= receivers; ++i) {
    out << "    component Receiver rcv" << i << "()\n";
  }
  out << "    connector Broadcast all(sender.send";
  for (long i = 1; i <= receivers; ++i) out << ", rcv" << i << ".recv";
  out << ")\n"
      << "  end\n"
      << "end\n";
}

/// Binds atoms n0..n{atoms-1} two by two with connectors of type `pair_type`, and the last one
/// alone with `solo_type` when `atoms` is odd, so that every atom can move.
void write_pairs(std::ostream& out, long atoms, const std::string& atom_type,
                 const std::string& pair_type, const std::string& solo_type) {
  out << "  compound type Top()\n";
  for (long i = 0; i < atoms; ++i) {
    out << "    component " << atom_type << " n" << i << "()\n";
  }
  for (long i = 0; i + 1 < atoms; i += 2) {
    out << "    connector " << pair_type << " c" << i / 2 << "(n" << i << ".step, n" << i + 1
        << ".step)\n";
  }
  if (atoms % 2 == 1) {
    out << "    connector " << solo_type << " c" << atoms / 2 << "(n" << atoms - 1 << ".step)\n";
  }
  out << "  end\n"
      << "end\n";
}

/// The package line and the types the two-by-two families share: a Tick port, Pair and Solo.
void write_pair_types(std::ostream& out, const std::string& package) {
  out << "package " << package << "\n"
      << "  port type Tick(int value)\n\n"
      << "  connector type Pair(Tick left, Tick right)\n"
      << "    define left right\n"
      << "  end\n\n"
      << "  connector type Solo(Tick alone)\n"
      << "    define alone\n"
      << "  end\n\n";
}

/// Writes `atoms` nodes meeting two by two on binary rendezvous (atoms / 2 connectors, plus one
/// singleton when `atoms` is odd); each node cycles through three places, counting its steps.
/// Every pair is always enabled: the engines' cost of finding and firing independent
/// interactions, with no work in the actions.
void write_rendezvous(std::ostream& out, const std::string& package, long atoms) {
  out << "// " << atoms << " atoms meeting two by two.\n";
  write_pair_types(out, package);
  out << "  atom type Cycler()\n"
      << "    data int count\n"
      << "    export port Tick step(count)\n\n"
      << "    place S0, S1, S2\n\n"
      << "    initial to S0 do { count = 0; }\n\n"
      << "    on step from S0 to S1 do { count = (count + 1) % 1000000; }\n"
      << "    on step from S1 to S2 do { count = (count + 1) % 1000000; }\n"
      << "    on step from S2 to S0 do { count = (count + 1) % 1000000; }\n"
      << "  end\n\n";
  write_pairs(out, atoms, "Cycler", "Pair", "Solo");
}

/// Assignments per transition of the `work` family, unless --work says otherwise.
constexpr long kWorkStatements = 200;

/// Writes the rendezvous pairs with heavy actions: each transition runs `statements` steps of
/// a linear congruential generator (multiplier 75, increment 74, modulus 65537, as the ZX81's),
/// without loops or externs, whose values stay below 2^23 so that they fit any int width. This
/// measures the cost of executing actions rather than scheduling.
void write_work(std::ostream& out, const std::string& package, long atoms, long statements) {
  out << "// " << atoms << " atoms meeting two by two, each step "
      << "running " << statements << " assignments.\n";
  write_pair_types(out, package);
  out << "  atom type Worker()\n"
      << "    data int a, rounds\n"
      << "    export port Tick step(a)\n\n"
      << "    place IDLE, BUSY\n\n"
      << "    initial to IDLE do { a = 1; rounds = 0; }\n\n";
  const char* moves[][2] = {{"IDLE", "BUSY"}, {"BUSY", "IDLE"}};
  for (const auto& move : moves) {
    out << "    on step from " << move[0] << " to " << move[1] << " do {\n";
    for (long i = 0; i < statements; ++i) {
      out << "      a = (a * 75 + 74) % 65537;\n";
    }
    out << "      rounds = (rounds + 1) % 1000000;\n"
        << "    }\n";
  }
  out << "  end\n\n";
  write_pairs(out, atoms, "Worker", "Pair", "Solo");
}

}  // namespace

int main(int argc, char** argv) {
  try {
    CLI::App app{"Writes a scalable BIP2 model whose root is Top()."};
    std::string family;
    long atoms = 0;
    std::string output;
    app.add_option("--family", family,
                   "chain (rendezvous between neighbours), priorities (the chain with a priority "
                   "rule per connector), broadcast, rendezvous (atoms meeting two by two) or "
                   "work (the same pairs with --work assignments per transition)")
        ->required()
        ->check(CLI::IsMember({"chain", "priorities", "broadcast", "rendezvous", "work"}));
    app.add_option("--atoms", atoms, "number of atom instances (at least 2)")
        ->required()
        ->check(CLI::Range(2L, 10'000'000L));
    long work = kWorkStatements;
    app.add_option("--work", work,
                   "work family: assignments per transition (engine benchmarks raise it so that "
                   "firing the two atoms of a pair in parallel can pay off)")
        ->check(CLI::Range(1L, 1'000'000L));
    app.add_option("-o,--output", output, "file to write; its stem names the package")->required();
    try {
      app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
      const int code = app.exit(error);
      return code == 0 ? kExitOk : kExitUsage;
    }

    const std::string package = std::filesystem::path(output).stem().string();
    if (!is_identifier(package)) {
      std::cerr << "gen_bip_models: error: the file name '" << output
                << "' must be an identifier followed by .bip (it names the package)\n";
      return kExitUsage;
    }
    std::ofstream out(output);
    if (!out) {
      std::cerr << "gen_bip_models: error: cannot write '" << output << "'\n";
      return kExitUsage;
    }
    // The command comes first, so that a generated file says how to make it again.
    out << "// Generated by: gen_bip_models --family " << family << " --atoms " << atoms
        << (family == "work" && work != kWorkStatements ? " --work " + std::to_string(work) : "")
        << " -o " << std::filesystem::path(output).filename().string() << "\n";
    if (family == "chain" || family == "priorities") {
      write_chain(out, package, atoms, family == "priorities");
    } else if (family == "rendezvous") {
      write_rendezvous(out, package, atoms);
    } else if (family == "work") {
      write_work(out, package, atoms, work);
    } else {
      write_broadcast(out, package, atoms);
    }
    out.close();
    if (!out) {
      std::cerr << "gen_bip_models: error: writing '" << output << "' failed\n";
      return kExitUsage;
    }
    return kExitOk;
  } catch (const std::exception& error) {
    std::cerr << "gen_bip_models: internal error: " << error.what() << "\n";
    return kExitInternal;
  } catch (...) {
    std::cerr << "gen_bip_models: internal error\n";
    return kExitInternal;
  }
}
