// The faces of elements of degree 2: the 3-node line of a 9-node
// quadrilateral and the 9-node face of a 27-node hexahedron, in the node
// order of deal.II's FE_Q(2), and their dual basis from its moments.
//
// The dual basis psi_j = sum_k a_jk N_k with A = D M^-1 (D_jj = integral
// N_j, M_jk = integral N_j N_k) exists for any face, M being a mass matrix;
// what the weighted gaps need is D_jj > 0, so that a node's weighted gap
// has the sign of the gap and its multiplier the sign of the pressure.
// The Lagrange faces have it (3-node line: 1/6, 2/3, 1/6 of the length;
// 9-node face: 1/36 at the corners, 1/9 at the mid-sides, 4/9 at the
// centre, of the area of a parallelogram), unlike the 8-node serendipity
// face, whose corner functions integrate to -1/12 and need the basis
// transformation of Popp, Wohlmuth, Gee and Wall (SIAM J. Sci. Comput. 34,
// 2012) first. This holds for whole faces only: the quadratic N_j change
// sign, so over a covered part D_jj can be negative (a 3-node line covered
// on xi in [-1, 0.3]: D = (0.576, -0.085, 1.082)), and the dual basis of
// the covered part, which partially covered linear faces use, would give
// that node a weighted gap of the wrong sign
// (tests/dual_basis_quadratic.cc).
#ifndef contact_dynamics_contact_quadratic_face_h
#define contact_dynamics_contact_quadratic_face_h

#include <contact_dynamics/contact/dual_basis_3d.h>

#include <array>
#include <vector>

namespace ContactDynamics
{
  namespace QuadraticFace
  {
    /**
     * The 3-node line at xi in [-1, 1] (the reference of 2-D faces here):
     * nodes at -1, 1 (the vertices) and 0 (the middle).
     */
    template <typename Number>
    std::array<Number, 3>
    line_shape(const Number &xi)
    {
      return {
        {xi * (xi - 1.) / 2., xi * (xi + 1.) / 2., (1. - xi) * (1. + xi)}};
    }

    /** d/dxi of line_shape(). */
    template <typename Number>
    std::array<Number, 3>
    line_shape_derivative(const Number &xi)
    {
      return {{xi - 0.5, xi + 0.5, -2. * xi}};
    }

    /** Quadratic Lagrange functions on [0, 1] with nodes 0, 1, 1/2. */
    template <typename Number>
    std::array<Number, 3>
    lagrange(const Number &t)
    {
      return {{(1. - t) * (1. - 2. * t), t * (2. * t - 1.), 4. * t * (1. - t)}};
    }

    /**
     * The 9-node face at (xi, eta) in [0, 1]^2 (the reference of 3-D faces
     * here): the vertices (0,0), (1,0), (0,1), (1,1), the middles of the
     * lines xi = 0, xi = 1, eta = 0, eta = 1, and the centre.
     */
    template <typename Number>
    std::array<Number, 9>
    quad_shape(const Number &xi, const Number &eta)
    {
      // (index of the 1-D function in xi, in eta) per node
      static constexpr unsigned int a[9] = {0, 1, 0, 1, 0, 1, 2, 2, 2};
      static constexpr unsigned int b[9] = {0, 0, 1, 1, 2, 2, 0, 1, 2};
      const auto                    x = lagrange(xi), y = lagrange(eta);
      std::array<Number, 9>         N;
      for (unsigned int j = 0; j < 9; ++j)
        N[j] = x[a[j]] * y[b[j]];
      return N;
    }

    /**
     * The coefficients a_jk of the dual basis psi_j = sum_k a_jk N_k on
     * what the points integrate: shape values N(x_q) and weights w_q (with
     * the face's Jacobian, so a curved face gets its own basis), covering
     * the whole face or the part that is in contact. Biorthogonal there:
     * sum_q w_q psi_j N_k = delta_jk sum_q w_q N_k; sum_j psi_j = 1.
     */
    template <typename Number, std::size_t n>
    std::array<std::array<Number, n>, n>
    dual_coefficients(const std::vector<std::array<Number, n>> &N,
                      const std::vector<Number>                &w)
    {
      std::array<Number, n>                D;
      std::array<std::array<Number, n>, n> M;
      D.fill(Number(0.));
      for (auto &row : M)
        row.fill(Number(0.));
      for (unsigned int q = 0; q < w.size(); ++q)
        ClippingGeometry::add_moments(N[q], w[q], D, M);
      return ClippingGeometry::dual_from_moments(D, M);
    }

    /** psi_j = sum_k a_jk N_k at one point. */
    template <typename Number, std::size_t n>
    std::array<Number, n>
    dual_values(const std::array<std::array<Number, n>, n> &a,
                const std::array<Number, n>                &N)
    {
      std::array<Number, n> psi;
      for (unsigned int j = 0; j < n; ++j)
        {
          psi[j] = Number(0.);
          for (unsigned int k = 0; k < n; ++k)
            psi[j] += a[j][k] * N[k];
        }
      return psi;
    }
  } // namespace QuadraticFace
} // namespace ContactDynamics

#endif
