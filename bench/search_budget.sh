#!/bin/sh
# The search's budget study (docs/search.md "Anytime"): every scene in config/ at budgets B, 2B,
# 4B, 8B (non-increasing best times) and at the default budget against 10x it (within 0.5 %).
#   bench/search_budget.sh [build dir] [B]     (needs -DZIPOPT_BUILD_BENCH=ON)
set -eu
build=${1:-build}
exec "$build/search_budget" "${2:-500}" config/*.ini
