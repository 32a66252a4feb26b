// Prints "x eps(x)" for the engine's viscoelastic restitution table at every
// x given on stdin, one per line, to 17 digits: what
// viscoelastic_table_accuracy.py compares with an independent solution.
#include <cstdio>
#include <iostream>

#include "simulate/engine/viscoelastic_restitution.h"

int main() {
  const auto& table = coolgas::ViscoelasticTable::get();
  double x = 0;
  while (std::cin >> x) std::printf("%.17g %.17g\n", x, table(x));
  return 0;
}
