// pathspace command line: `render`, `info`, `compare` and `study` (docs/cli.md). Usage mistakes exit
// with status 2 and one line on stderr; failures while running exit with status 1 (cli_app.h).
#include "cli_app.h"

int main(int argc, char** argv) { return pathspace::cli::run_cli(argc, argv); }
