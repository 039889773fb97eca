// Verilator coverage of the coverage build (cmake -DSC_COVERAGE=ON, see
// scripts/coverage.py). A test process builds and destroys many Verilated
// tops, each with its own context: when one is destroyed its counters are
// added to one table per process, written at exit to
// $SC_COVERAGE_DIR/<program>-<pid>.dat in verilator_coverage's format. A
// top's counters live in the top, so they are taken before it goes.
// Without SC_COVERAGE_DIR, or in a build without coverage, nothing happens.
#pragma once

class VerilatedContext;

namespace sc {

void coverage_collect(VerilatedContext& ctx);

}  // namespace sc
