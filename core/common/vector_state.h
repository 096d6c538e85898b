#pragma once

namespace probecycle {

// Clears the upper halves of the AVX registers (vzeroupper) on a CPU that has
// them; elsewhere nothing. The core is built for plain x86-64, so its floating
// point is legacy SSE. After AVX code that leaves the upper halves in use (some
// of what a Qt window runs does), every switch between that and the VEX code
// of the C library's exp() costs a state transition or a merge with the upper
// halves (Intel, "Intel AVX State Transitions: Migrating SSE Code to AVX";
// Intel 64 and IA-32 Architectures Optimization Reference Manual, "Mixing AVX
// code with SSE code"). Measured in probecycle-ui-bench: the window's
// recompute on the Fanuc-type preset took 7.6 ms with the upper halves left in
// use and 1.1 ms after clearing them. The window calls this before it hands a
// computation to the core.
void clear_vector_upper_state();

}  // namespace probecycle
