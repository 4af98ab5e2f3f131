#!/usr/bin/env bash
# Fuzzes the pbrt-v3 scene importer: scripts/fuzz.sh pbrt [seconds]
# (see there; SAFEGI_FUZZ_RUNS / SAFEGI_FUZZ_SEED for a fixed run, SAFEGI_FUZZ_SEEDS=DIR for more seed scenes).
exec "$(dirname "$0")/fuzz.sh" pbrt "$@"
