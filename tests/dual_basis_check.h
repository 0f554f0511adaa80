// Checks of a bilinear dual basis (ClippingGeometry::dual_coefficients) by
// an independent 5 x 5 Gauss rule, for the 3-D mortar geometry tests.
#ifndef contact_dynamics_tests_dual_basis_check_h
#define contact_dynamics_tests_dual_basis_check_h

#include <contact_dynamics/contact/clipping_geometry.h>

#include <algorithm>
#include <array>
#include <cmath>

struct DualBasisErrors
{
  double biorthogonality = 0; // max |integral psi_j N_k - delta_jk int N_k|
  double unity           = 0; // max |sum_j psi_j - 1| at the points
};

// psi_j = sum_k a_jk N_k over [xi0, xi1] x [eta0, eta1] of the reference
// square, with the area element dA(xi, eta) per unit reference area
template <typename AreaElement>
DualBasisErrors
dual_basis_errors(const std::array<std::array<double, 4>, 4> &a,
                  const double                                xi0,
                  const double                                xi1,
                  const double                                eta0,
                  const double                                eta1,
                  const AreaElement                          &area_element)
{
  const double    g[5]        = {-0.906179845938664,
                                 -0.538469310105683,
                                 0,
                                 0.538469310105683,
                                 0.906179845938664};
  const double    w[5]        = {0.236926885056189,
                                 0.478628670499366,
                                 0.568888888888889,
                                 0.478628670499366,
                                 0.236926885056189};
  double          psi_n[4][4] = {}, n_k[4] = {};
  DualBasisErrors errors;
  for (unsigned int i = 0; i < 5; ++i)
    for (unsigned int l = 0; l < 5; ++l)
      {
        const double xi  = xi0 + (xi1 - xi0) * (1 + g[i]) / 2;
        const double eta = eta0 + (eta1 - eta0) * (1 + g[l]) / 2;
        const double da =
          area_element(xi, eta) * (xi1 - xi0) * (eta1 - eta0) * w[i] * w[l] / 4;
        const auto N       = ContactDynamics::ClippingGeometry::shape(xi, eta);
        double     sum_psi = 0;
        for (unsigned int j = 0; j < 4; ++j)
          {
            double psi = 0;
            for (unsigned int k = 0; k < 4; ++k)
              psi += a[j][k] * N[k];
            sum_psi += psi;
            for (unsigned int k = 0; k < 4; ++k)
              psi_n[j][k] += psi * N[k] * da;
          }
        for (unsigned int k = 0; k < 4; ++k)
          n_k[k] += N[k] * da;
        errors.unity = std::max(errors.unity, std::abs(sum_psi - 1));
      }
  for (unsigned int j = 0; j < 4; ++j)
    for (unsigned int k = 0; k < 4; ++k)
      errors.biorthogonality =
        std::max(errors.biorthogonality,
                 std::abs(psi_n[j][k] - (j == k ? n_k[k] : 0.)));
  return errors;
}

#endif
