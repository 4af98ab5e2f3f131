#!/usr/bin/env bash
# Fuzzes safegi-lsp's message reader and dispatcher: scripts/fuzz.sh lsp [seconds]
# (see there; SAFEGI_FUZZ_RUNS / SAFEGI_FUZZ_SEED for a fixed run).
exec "$(dirname "$0")/fuzz.sh" lsp "$@"
