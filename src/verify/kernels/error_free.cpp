// The error-free transformations compiled with the library's own flags (error_free.h), so that
// tests/test_oracle_kernels.cpp checks the very code the kernels run: a build that contracts
// a·b + c into a fused multiply-add breaks split and Dekker's product, and those tests fail.
// Also the kernels' test switch (oracle_fast.h).
#include "error_free.h"
#include "expansion.h"
#include "../oracle_fast.h"

namespace shadowproof::detail {
bool kernels_exact_only = false;
}  // namespace shadowproof::detail

namespace shadowproof::detail::compiled {

void two_sum(double a, double b, double& s, double& e) { detail::two_sum(a, b, s, e); }
void split(double x, double& hi, double& lo) { detail::split(x, hi, lo); }
void two_product(double a, double b, double& p, double& e) { detail::two_product(a, b, p, e); }
void two_product_dekker(double a, double b, double& p, double& e) { detail::two_product_dekker(a, b, p, e); }

int expansion_of(const double* terms, int n, double* components) {
  int m = 0;
  for (int i = 0; i < n; ++i) m = grow_expansion(components, m, terms[i]);
  return m;
}

}  // namespace shadowproof::detail::compiled
