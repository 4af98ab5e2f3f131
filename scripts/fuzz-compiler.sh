#!/usr/bin/env bash
# Fuzzes the whole safeglslc pipeline: scripts/fuzz.sh compiler [seconds]
# (see there; SAFEGI_FUZZ_RUNS / SAFEGI_FUZZ_SEED for a fixed run).
exec "$(dirname "$0")/fuzz.sh" compiler "$@"
