#pragma once
// How `femto compare` shows a Comparison: a table for people, JSON for scripts
// (tools/compare/speed_vs_error.py reads it). Fields: docs/compare.md.
#include <ostream>

#include <femto/analysis/compare_files.h>

namespace femto::cli {

void printComparisonTable(std::ostream& os, const Comparison& c);
void writeComparisonJson(std::ostream& os, const Comparison& c);

}  // namespace femto::cli
