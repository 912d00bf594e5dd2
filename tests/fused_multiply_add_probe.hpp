#pragma once
// a * b + c, compiled apart (fused_multiply_add_probe.cpp) for a CPU that
// can fuse it into one rounding, so that the test sees what the project's
// compile options let the compiler do with such a sum.
double product_plus_sum(double a, double b, double c);
