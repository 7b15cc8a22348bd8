# Sourced by the benchmark scripts (from the repository root): where a result
# comes from, for the header of each generated docs/BENCHMARKS.md section.
#   commit  short hash of HEAD
#   dirty   " (with uncommitted changes)" when src, tools or scenes differ from HEAD
#   model   the CPU model (lscpu)
commit=$(git rev-parse --short HEAD)
dirty=$(git diff --quiet HEAD -- src tools scenes 2>/dev/null || echo " (with uncommitted changes)")
model=$(lscpu | sed -n 's/^Model name: *//p' | head -n 1)
