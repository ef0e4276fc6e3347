#!/usr/bin/env bash
# The stability study's table of outcomes from its results.
# Usage: reports/stability/make_section.sh [BIN_DIR] [RESULTS_DIR] [OUT_DIR]
#   defaults: build/bin, results/stability/paper, reports/stability (receives table.md)
# Exit status 1 if a case is not acceptable (ran without finite values or beyond the closure
# limit, or stopped without a message): the table says which.
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
bin=${1:-$here/build/bin}
results=${2:-$here/results/stability/paper}
out=${3:-$here/reports/stability}
mkdir -p "$out"
"$bin/compare-runs" stability "$results" "$out" --report-only   # ⚠ cases are marked in the table
