#pragma once
// The lab's engine as C functions over one session: what the page's Web Worker
// calls (lab/web/worker-main.js, through WebAssembly) and what the native check
// calls (lab_check.cpp), the same code either way.
//
// A failing call returns -1 and lab_message() says why, in the library's words
// ("particles.r = 1.5 is not allowed; allowed: ..."); no call throws. Arrays
// and values are those of the last frame, by name (lab_array, lab_value):
//   arrays: x v m (the bodies, sorted by x), exact_v exact_rho (Hopf-Lax cell
//     averages; empty on a line), shock_x shock_v shock_mass (its shocks),
//     hull_x hull_v hull_m (the exact sticky gas, r = 0 only), cluster_x
//     cluster_v cluster_m (clusters of two particles' mass or more);
//   values: t T collisions inelastic elastic merges dissipated mass alive L
//     ring particle_mass stop_position, and the settings it runs with: N r
//     delta sticky seed.
// A pointer stays valid until the next lab_start or lab_advance.
extern "C" {

// A new session (LabSettings); 0, or -1 with the old session unchanged.
int lab_start(const char* scene, double N, double r, double delta, int sticky, int line, double seed);
// Advances to time t with a budget of collisions (0: none) and computes the
// frame with the exact solution on `cells` cells: 0 t reached, 1 stopped by
// the budget (t not reached), 2 the run has ended (collapse or rounding stall), -1 error.
int lab_advance(double t, double budget, int cells);
const double* lab_array(const char* name);  // null for an unknown name
int lab_size(const char* name);             // -1 for an unknown name
double lab_value(const char* name);         // NaN for an unknown name
const char* lab_message();
// Every array and value of the last frame as one line each, "name count
// fnv1a-64 of the bits": what the check of the WebAssembly build compares.
const char* lab_digest();
}
