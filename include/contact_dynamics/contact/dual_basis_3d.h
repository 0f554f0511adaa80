// The dual basis of a bilinear face (or of its covered part) from its
// moments, and Gauss points of a whole face (clipping_geometry.h).
#ifndef contact_dynamics_contact_dual_basis_3d_h
#define contact_dynamics_contact_dual_basis_3d_h

#include <contact_dynamics/contact/face_projection_3d.h>

namespace ContactDynamics
{
  namespace ClippingGeometry
  {
    /** A quadrature point in a face's reference square, weight with area. */
    template <typename Number>
    struct FacePoint
    {
      Number xi, eta, weight;
    };

    /** D_j += w N_j and M_jk += w N_j N_k for one point. */
    template <typename Number, std::size_t n>
    void
    add_moments(const std::array<Number, n>          &N,
                const Number                         &w,
                std::array<Number, n>                &D,
                std::array<std::array<Number, n>, n> &M)
    {
      for (unsigned int j = 0; j < n; ++j)
        {
          D[j] += w * N[j];
          for (unsigned int k = 0; k < n; ++k)
            M[j][k] += w * N[j] * N[k];
        }
    }

    /**
     * A = D M^-1 from D_jj = integral N_j and M_jk = integral N_j N_k, for
     * a face of n nodes.
     */
    template <typename Number, std::size_t n>
    std::array<std::array<Number, n>, n>
    dual_from_moments(const std::array<Number, n>         &D,
                      std::array<std::array<Number, n>, n> M)
    {
      // M^-1 by Gauss-Jordan elimination with partial pivoting on values
      std::array<std::array<Number, n>, n> inverse{};
      for (unsigned int j = 0; j < n; ++j)
        for (unsigned int k = 0; k < n; ++k)
          inverse[j][k] = Number(j == k ? 1. : 0.);
      for (unsigned int c = 0; c < n; ++c)
        {
          unsigned int pivot = c;
          for (unsigned int r = c + 1; r < n; ++r)
            if (std::abs(value_of(M[r][c])) > std::abs(value_of(M[pivot][c])))
              pivot = r;
          std::swap(M[c], M[pivot]);
          std::swap(inverse[c], inverse[pivot]);
          const Number diagonal = M[c][c];
          for (unsigned int k = 0; k < n; ++k)
            {
              M[c][k] /= diagonal;
              inverse[c][k] /= diagonal;
            }
          for (unsigned int r = 0; r < n; ++r)
            if (r != c)
              {
                const Number factor = M[r][c];
                for (unsigned int k = 0; k < n; ++k)
                  {
                    M[r][k] -= factor * M[c][k];
                    inverse[r][k] -= factor * inverse[c][k];
                  }
              }
        }
      std::array<std::array<Number, n>, n> a;
      for (unsigned int j = 0; j < n; ++j)
        for (unsigned int k = 0; k < n; ++k)
          a[j][k] = D[j] * inverse[j][k];
      return a;
    }

    /**
     * Coefficients a_jk of the dual basis psi_j = sum_k a_jk N_k of a face,
     * biorthogonal to N on what the points integrate: A = D M^-1 with
     * D_jj = sum w N_j and M_jk = sum w N_j N_k (the whole face, or its
     * covered part, as in the 2-D dual_coefficients). Sum_j psi_j = 1.
     */
    template <typename Number>
    std::array<std::array<Number, 4>, 4>
    dual_coefficients(const std::vector<FacePoint<Number>> &points)
    {
      std::array<Number, 4>                D{};
      std::array<std::array<Number, 4>, 4> M{};
      for (auto &row : M)
        row.fill(Number(0.));
      D.fill(Number(0.));
      for (const auto &q : points)
        add_moments(shape(q.xi, q.eta), q.weight, D, M);
      return dual_from_moments(D, M);
    }

    /**
     * 2 x 2 Gauss points of the whole face x, with the area element:
     * exact for the products N_j N_k |dx/dxi x dx/deta| of a flat face.
     */
    template <typename Number>
    std::vector<FacePoint<Number>>
    face_points(const std::array<Vec3<Number>, 4> &x)
    {
      std::vector<FacePoint<Number>> points;
      const double                   g = 0.5 / std::sqrt(3.);
      for (const double xi : {0.5 - g, 0.5 + g})
        for (const double eta : {0.5 - g, 0.5 + g})
          {
            const auto t = tangents(x, Number(xi), Number(eta));
            points.push_back(
              {Number(xi), Number(eta), norm(cross(t[0], t[1])) / 4.});
          }
      return points;
    }
  } // namespace ClippingGeometry
} // namespace ContactDynamics

#endif
