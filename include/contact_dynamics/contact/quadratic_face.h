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

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <contact_dynamics/contact/dual_basis_3d.h>

#include <array>
#include <cmath>
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

    /** d/dt of lagrange(). */
    inline std::array<double, 3>
    lagrange_derivative(const double t)
    {
      return {{4. * t - 3., 4. * t - 1., 4. - 8. * t}};
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
     * d/dxi and d/deta of quad_shape() (they do not depend on the face's
     * positions: plain numbers).
     */
    inline std::array<std::array<double, 9>, 2>
    quad_shape_gradients(const double xi, const double eta)
    {
      static constexpr unsigned int a[9] = {0, 1, 0, 1, 0, 1, 2, 2, 2};
      static constexpr unsigned int b[9] = {0, 0, 1, 1, 2, 2, 0, 1, 2};
      const auto                    x = lagrange(xi), y = lagrange(eta);
      const auto dx = lagrange_derivative(xi), dy = lagrange_derivative(eta);
      std::array<std::array<double, 9>, 2> G;
      for (unsigned int j = 0; j < 9; ++j)
        {
          G[0][j] = dx[a[j]] * y[b[j]];
          G[1][j] = x[a[j]] * dy[b[j]];
        }
      return G;
    }

    /** Nodes of a face of degree 2: the 3-node line, the 9-node face. */
    template <int dim>
    constexpr unsigned int n_nodes = dim == 2 ? 3 : 9;

    /** Shape functions of a face of degree 2 at q and their gradients. */
    template <int dim>
    struct Shape
    {
      std::array<double, n_nodes<dim>>                      N;
      std::array<std::array<double, n_nodes<dim>>, dim - 1> dN;
    };

    /** At q in [0,1]^(dim-1). */
    template <int dim>
    Shape<dim>
    shape(const dealii::Point<dim - 1> &q)
    {
      Shape<dim> s;
      if constexpr (dim == 2)
        {
          s.N     = lagrange(q[0]);
          s.dN[0] = lagrange_derivative(q[0]);
        }
      else
        {
          s.N  = quad_shape(q[0], q[1]);
          s.dN = quad_shape_gradients(q[0], q[1]);
        }
      return s;
    }

    /**
     * The area (length) element |dx/dxi| or |dx/dxi x dx/deta| of the face
     * with nodes x where the shape gradients are dN.
     */
    template <int dim, typename Number>
    Number
    area_element(
      const std::array<std::array<double, n_nodes<dim>>, dim - 1>    &dN,
      const std::array<dealii::Tensor<1, dim, Number>, n_nodes<dim>> &x)
    {
      using std::sqrt;
      std::array<dealii::Tensor<1, dim, Number>, dim - 1> t;
      for (unsigned int k = 0; k < dim - 1; ++k)
        for (unsigned int j = 0; j < n_nodes<dim>; ++j)
          t[k] += Number(dN[k][j]) * x[j];
      if constexpr (dim == 2)
        return sqrt(t[0] * t[0]);
      else
        {
          const auto  &a = t[0], &b = t[1];
          const Number c0 = a[1] * b[2] - a[2] * b[1],
                       c1 = a[2] * b[0] - a[0] * b[2],
                       c2 = a[0] * b[1] - a[1] * b[0];
          return sqrt(c0 * c0 + c1 * c1 + c2 * c2);
        }
    }

    /**
     * The node positions of the face q in [0,1]^(dim-1) of a 3-node line
     * (dim = 2) or 9-node face (dim = 3), relative to its vertices in
     * the order of face_to_cell_vertices: (the vertices, then the others).
     */
    template <int dim>
    std::vector<std::array<double, dim - 1>>
    node_coordinates()
    {
      if constexpr (dim == 2)
        return {{{0.}}, {{1.}}, {{0.5}}};
      else
        return {{{0., 0.}},
                {{1., 0.}},
                {{0., 1.}},
                {{1., 1.}},
                {{0., 0.5}},
                {{1., 0.5}},
                {{0.5, 0.}},
                {{0.5, 1.}},
                {{0.5, 0.5}}};
    }

    /**
     * The node permutation that reverses a face's orientation: in 2-D the
     * vertices swap, in 3-D xi and eta do.
     */
    template <int dim>
    std::vector<std::pair<unsigned int, unsigned int>>
    reversal_swaps()
    {
      if constexpr (dim == 2)
        return {{0, 1}};
      else
        return {{1, 2}, {4, 6}, {5, 7}};
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
