// The 3-D mortar integrals (ClippingGeometry::integrate_segment) on two
// non-matching, non-aligned flat meshes a distance delta apart: a 3 x 3
// secondary mesh of the unit square in a tilted plane, and a sheared,
// rotated 4 x 4 primary mesh covering it. Parallelogram faces make every
// integrand a polynomial of degree 4 in the plane, which the 6-point rule
// integrates exactly, so the identities of dual mortar hold to round-off:
// with the primary faces facing the secondary side (as two bodies' faces
// do) and with the same orientation:
// - the D_j of the secondary nodes sum to the area of the surface (1);
// - the weighted gap of every node is delta D_j (the normalized gap is the
//   distance);
// - sum_k M_jk = D_j (a rigid translation of the primary side moves every
//   weighted gap alike);
// - the mortar projection D^-1 M reproduces a linear field at the
//   secondary nodes (biorthogonality);
// and the AD derivatives of a weighted gap with respect to primary
// coordinates (moving the clip vertices) match central differences.
// A partially covered face (two primary faces over 60 % of it): the dual
// basis built from the segments' points is biorthogonal on the covered part
// under an independent 5 x 5 Gauss rule over that rectangle, sums to 1, and
// gives every node the normalized gap delta.
#include <deal.II/differentiation/ad/sacado_math.h>
#include <deal.II/differentiation/ad/sacado_number_types.h>
#include <deal.II/differentiation/ad/sacado_product_types.h>

#include <contact_dynamics/contact/clipping_geometry.h>

#include "dual_basis_check.h"
#include "tests.h"

#include <Sacado.hpp>
#include <functional>

using namespace dealii;
using namespace ContactDynamics::ClippingGeometry;

namespace
{
  using V = Vec3<double>;

  V
  vec(const double x, const double y, const double z)
  {
    V v;
    v[0] = x;
    v[1] = y;
    v[2] = z;
    return v;
  }

  struct Mesh
  {
    std::vector<V>                           nodes;
    std::vector<std::array<unsigned int, 4>> faces;
  };

  // an n x n grid of [a, b]^2 mapped by `map` (lexicographic face nodes)
  Mesh
  grid(const unsigned int                                  n,
       const double                                        a,
       const double                                        b,
       const std::function<V(const double, const double)> &map)
  {
    Mesh mesh;
    for (unsigned int j = 0; j <= n; ++j)
      for (unsigned int i = 0; i <= n; ++i)
        mesh.nodes.push_back(map(a + (b - a) * i / n, a + (b - a) * j / n));
    for (unsigned int j = 0; j < n; ++j)
      for (unsigned int i = 0; i < n; ++i)
        {
          const unsigned int k = i + (n + 1) * j;
          mesh.faces.push_back({{k, k + 1, k + n + 1, k + n + 2}});
        }
    return mesh;
  }

  template <typename Number>
  std::array<Vec3<Number>, 4>
  face_nodes(const Mesh &mesh, const unsigned int f)
  {
    std::array<Vec3<Number>, 4> x;
    for (unsigned int a = 0; a < 4; ++a)
      for (unsigned int d = 0; d < 3; ++d)
        x[a][d] = mesh.nodes[mesh.faces[f][a]][d];
    return x;
  }

  // the tilted plane: origin, two orthonormal in-plane directions, normal
  const V          origin = vec(0.3, -0.2, 1.0);
  const V          e1     = vec(0.8, 0.0, 0.6);
  const V          e2     = vec(-0.36, 0.8, 0.48);
  const V          nu     = cross(e1, e2);
  constexpr double delta  = 0.0125;
} // namespace

int
main()
{
  initlog();
  const Mesh secondary = grid(3, 0, 1, [](const double x, const double y) {
    return origin + x * e1 + y * e2;
  });
  // sheared and rotated by 17 degrees about the square's center, lifted by
  // delta along the normal
  const double c = std::cos(17 * M_PI / 180), s = std::sin(17 * M_PI / 180);
  const Mesh   primary =
    grid(4, -0.4, 1.4, [&](const double x0, const double y0) {
      const double x = x0 + 0.15 * (y0 - 0.5) - 0.5, y = y0 - 0.5;
      return origin + (0.5 + c * x - s * y) * e1 + (0.5 + s * x + c * y) * e2 +
             delta * nu;
    });

  // the primary faces as their own body numbers them (normals facing the
  // secondary side), and with the opposite orientation
  const std::array<V, 4> normals{{nu, nu, nu, nu}};
  Mesh                   facing = primary;
  for (auto &f : facing.faces)
    std::swap(f[1], f[2]);
  for (const Mesh *mesh : std::array<const Mesh *, 2>{{&facing, &primary}})
    {
      const std::string name =
        mesh == &facing ? "facing primary faces: " : "same orientation: ";
      const unsigned int n_s = secondary.nodes.size(), n_m = mesh->nodes.size();
      std::vector<double>              D(n_s, 0.), gap(n_s, 0.);
      std::vector<std::vector<double>> M(n_s, std::vector<double>(n_m, 0.));
      for (unsigned int f = 0; f < secondary.faces.size(); ++f)
        {
          const auto xs   = face_nodes<double>(secondary, f);
          const auto dual = dual_coefficients(face_points(xs));
          for (unsigned int g = 0; g < mesh->faces.size(); ++g)
            {
              SegmentIntegrals<double> r;
              if (!integrate_segment(xs,
                                     normals,
                                     face_nodes<double>(*mesh, g),
                                     dual,
                                     1e-12,
                                     r))
                continue;
              for (unsigned int j = 0; j < 4; ++j)
                {
                  const unsigned int J = secondary.faces[f][j];
                  D[J] += r.D[j];
                  gap[J] += r.gap[j];
                  for (unsigned int k = 0; k < 4; ++k)
                    M[J][mesh->faces[g][k]] += r.M[j][k];
                }
            }
        }
      double     total = 0, gap_error = 0, row_error = 0, linear_error = 0;
      const auto linear = [](const V &x) {
        return 0.7 + x[0] - 2 * x[1] + 3 * x[2];
      };
      for (unsigned int j = 0; j < n_s; ++j)
        {
          total += D[j];
          gap_error  = std::max(gap_error, std::abs(gap[j] / D[j] - delta));
          double row = 0, projected = 0;
          for (unsigned int k = 0; k < n_m; ++k)
            {
              row += M[j][k];
              projected += M[j][k] * linear(mesh->nodes[k]);
            }
          row_error = std::max(row_error, std::abs(row - D[j]) / D[j]);
          // the primary nodes lie delta above: the field there is shifted by
          // delta times its gradient along the normal
          const double expected =
            linear(secondary.nodes[j]) + delta * (nu * vec(1, -2, 3));
          linear_error =
            std::max(linear_error, std::abs(projected / D[j] - expected));
        }
      record_measured(name + "normalized gap error", gap_error, 0, 1e-13);
      record_measured(name + "row sum error", row_error, 0, 1e-13);
      record_measured(name + "linear field error", linear_error, 0, 1e-12);
      check_close(name + "sum of D_j: the surface's area", total, 1, 1e-13);
      check_close(name + "normalized weighted gaps equal the distance",
                  gap_error,
                  0,
                  1e-13);
      check_close(name + "sum_k M_jk = D_j", row_error, 0, 1e-13);
      check_close(name + "D^-1 M reproduces a linear field",
                  linear_error,
                  0,
                  1e-12);
    }

  // derivatives of the weighted gap of the secondary face 4's node 0 with
  // respect to a primary node's three coordinates
  {
    using AD             = Sacado::Fad::DFad<double>;
    const unsigned int f = 4, node = 6; // a primary node over that face
    const auto         weighted_gap = [&](const Mesh &m) {
      double     sum = 0;
      const auto xs  = face_nodes<double>(secondary, f);
      for (unsigned int g = 0; g < m.faces.size(); ++g)
        {
          SegmentIntegrals<double> r;
          if (integrate_segment(xs,
                                normals,
                                face_nodes<double>(m, g),
                                dual_coefficients(face_points(xs)),
                                1e-12,
                                r))
            sum += r.gap[0];
        }
      return sum;
    };
    std::array<double, 3>   ad{{0, 0, 0}};
    const auto              xs = face_nodes<AD>(secondary, f);
    std::array<Vec3<AD>, 4> ns;
    for (unsigned int a = 0; a < 4; ++a)
      for (unsigned int d = 0; d < 3; ++d)
        ns[a][d] = nu[d];
    for (unsigned int g = 0; g < primary.faces.size(); ++g)
      {
        auto xm = face_nodes<AD>(primary, g);
        for (unsigned int a = 0; a < 4; ++a)
          if (primary.faces[g][a] == node)
            for (unsigned int d = 0; d < 3; ++d)
              xm[a][d] = AD(3, d, primary.nodes[node][d]);
        SegmentIntegrals<AD> r;
        if (integrate_segment(xs,
                              ns,
                              xm,
                              dual_coefficients(face_points(xs)),
                              1e-12,
                              r))
          for (unsigned int d = 0; d < 3; ++d)
            ad[d] += r.gap[0].dx(d);
      }
    double       largest = 0, scale = 0;
    const double h = 1e-6;
    for (unsigned int d = 0; d < 3; ++d)
      {
        Mesh plus = primary, minus = primary;
        plus.nodes[node][d] += h;
        minus.nodes[node][d] -= h;
        const double fd = (weighted_gap(plus) - weighted_gap(minus)) / (2 * h);
        largest         = std::max(largest, std::abs(ad[d] - fd));
        scale           = std::max(scale, std::abs(fd));
      }
    record_measured("AD against differences, relative",
                    largest / scale,
                    0,
                    1e-6);
    check_true("the primary node moves the weighted gap", scale > 1e-3);
    check_close("weighted gap: AD derivatives against central differences",
                largest / scale,
                0,
                1e-6);
  }

  // a face of which [0.4, 1] x [0, 1] is covered, by two primary faces
  {
    std::array<V, 4> xs, ns, lower, upper;
    const double     corner[4][2] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
    for (unsigned int a = 0; a < 4; ++a)
      {
        xs[a] = vec(corner[a][0], corner[a][1], 0);
        ns[a] = vec(0, 0, 1);
        lower[a] =
          vec(0.4 + 1.3 * corner[a][0], -0.3 + 0.9 * corner[a][1], delta);
        upper[a] =
          vec(0.4 + 1.3 * corner[a][0], 0.6 + 0.9 * corner[a][1], delta);
      }
    std::vector<SegmentPoint<double>> points;
    const bool overlap = segment_points(xs, ns, lower, 1e-12, points) &&
                         segment_points(xs, ns, upper, 1e-12, points);
    check_true("partial coverage: both primary faces overlap", overlap);
    const auto dual = dual_coefficients(secondary_points(points));
    // the covered rectangle of the flat unit face
    const auto   e  = dual_basis_errors(dual, 0.4, 1, 0, 1, [](double, double) {
      return 1.;
    });
    const double bi = e.biorthogonality, unity = e.unity;
    record_measured("partial coverage: biorthogonality error", bi, 0, 1e-13);
    check_close("partial coverage: biorthogonal on the covered part",
                bi,
                0,
                1e-13);
    check_close("partial coverage: sum of psi is 1", unity, 0, 1e-13);
    SegmentIntegrals<double>          r;
    std::vector<SegmentPoint<double>> lower_points, upper_points;
    segment_points(xs, ns, lower, 1e-12, lower_points);
    segment_points(xs, ns, upper, 1e-12, upper_points);
    add_segment_integrals(xs, ns, lower, dual, lower_points, r);
    add_segment_integrals(xs, ns, upper, dual, upper_points, r);
    double gap_error = 0;
    for (unsigned int j = 0; j < 4; ++j)
      gap_error = std::max(gap_error, std::abs(r.gap[j] / r.D[j] - delta));
    check_close("partial coverage: normalized gaps equal the distance",
                gap_error,
                0,
                1e-13);
    check_close("partial coverage: covered area", r.area, 0.6, 1e-14);
  }
}
