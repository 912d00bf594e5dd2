// Built for a CPU with fused multiply-add (tests/CMakeLists.txt: -mfma on
// x86-64; aarch64 has it always), with the project's options otherwise.
#include "fused_multiply_add_probe.hpp"

double product_plus_sum(double a, double b, double c) { return a * b + c; }
