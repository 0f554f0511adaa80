// The geometry of 3-D mortar segments (clipping_geometry.h), against exact
// values:
// 1. clipping of squares and polygons in the degenerate configurations a
//    mesh produces: full coverage, a shared edge, a shared corner, a vertex
//    on an edge, coincident vertices, a sliver narrower than the tolerance
//    and one wider, a face containing the other, disjoint faces, a clip
//    polygon with an edge of length 0 (a degenerate face), a 45
//    degree rotation (the regular octagon, area 2 (sqrt 2 - 1)), a cut
//    through two vertices; areas against the exact values, no duplicate
//    vertices;
// 2. the fan triangulation covers the polygon: triangle areas sum to the
//    polygon's and are positive; the 6-point rule integrates x^2 y^2 over a
//    clip polygon exactly;
// 3. faces in a tilted plane projected onto it keep their 3-D areas;
// 4. the projection of a point onto a warped bilinear face along a
//    direction recovers the parameters it was made from, and its AD
//    derivatives match central differences; so does the derivative of a
//    clip area with respect to a vertex, against the exact derivative;
// 5. the dual basis of a bilinear face: on a square the closed form
//    psi_0 = 4 N_0 - 2 N_1 - 2 N_2 + N_3 (Wohlmuth 2000, lexicographic
//    numbering); on a flat distorted quadrilateral biorthogonality checked
//    with a 5 x 5 Gauss rule, independent of the 2 x 2 rule that built it;
// 6. nodal normals averaged from the corner normals of the faces around a
//    node: (1, 1, 1) / sqrt 3 at a cube's corner, exact on a flat face.
#include <deal.II/differentiation/ad/sacado_math.h>
#include <deal.II/differentiation/ad/sacado_number_types.h>
#include <deal.II/differentiation/ad/sacado_product_types.h>

#include <contact_dynamics/contact/clipping_geometry.h>

#include "dual_basis_check.h"
#include "tests.h"

#include <Sacado.hpp>

using namespace dealii;
using namespace ContactDynamics::ClippingGeometry;

namespace
{
  using P                    = Point2<double>;
  using Poly                 = Polygon<double>;
  constexpr double tolerance = 1e-12;

  Poly
  square(const double x0, const double y0, const double size = 1.)
  {
    return {{{x0, y0}},
            {{x0 + size, y0}},
            {{x0 + size, y0 + size}},
            {{x0, y0 + size}}};
  }

  Poly
  rotated(const Poly &p, const double angle, const P center)
  {
    Poly r;
    for (const auto &v : p)
      {
        const double x = v[0] - center[0], y = v[1] - center[1];
        r.push_back({{center[0] + std::cos(angle) * x - std::sin(angle) * y,
                      center[1] + std::sin(angle) * x + std::cos(angle) * y}});
      }
    return r;
  }

  bool
  no_duplicates(const Poly &p)
  {
    for (unsigned int i = 0; i < p.size(); ++i)
      for (unsigned int j = i + 1; j < p.size(); ++j)
        if (std::hypot(p[i][0] - p[j][0], p[i][1] - p[j][1]) <= tolerance)
          return false;
    return true;
  }

  void
  check_clip(const std::string &name,
             const Poly        &subject,
             const Poly        &clip,
             const double       area,
             const unsigned int vertices)
  {
    const Poly result = clip_polygon(subject, clip, tolerance);
    check_close(name + ": area",
                result.empty() ? 0. : signed_area(result),
                area,
                1e-14);
    check_true(name + ": " + std::to_string(vertices) + " vertices",
               result.size() == vertices);
    check_true(name + ": no duplicate vertices", no_duplicates(result));
    double sum = 0, smallest = 1;
    for (const auto &t : triangulate(result))
      {
        const double a = signed_area(Poly(t.begin(), t.end()));
        sum += a;
        smallest = std::min(smallest, a);
      }
    check_close(name + ": triangles sum to the area", sum, area, 1e-14);
    check_true(name + ": triangles positive", result.empty() || smallest > 0);
  }
} // namespace

int
main()
{
  initlog();

  // 1. and 2.
  const Poly unit = square(0, 0);
  check_clip("identical squares", unit, unit, 1, 4);
  check_clip("shared edge", square(1, 0), unit, 0, 0);
  check_clip("shared corner", square(1, 1), unit, 0, 0);
  check_clip("disjoint", square(2, 0.3), unit, 0, 0);
  check_clip("quarter overlap", square(0.5, 0.5), unit, 0.25, 4);
  check_clip("contained", square(0.25, 0.25, 0.5), unit, 0.25, 4);
  check_clip("containing", square(-1, -1, 3), unit, 1, 4);
  check_clip("vertices on the edges (diamond)",
             {{{0.5, 0}}, {{1, 0.5}}, {{0.5, 1}}, {{0, 0.5}}},
             unit,
             0.5,
             4);
  check_clip("half along a shared edge", square(0, 0.5), unit, 0.5, 4);
  check_clip("sliver 1e-9 wide", square(1 - 1e-9, 0), unit, 1e-9, 4);
  check_clip("sliver below the tolerance", square(1 - 1e-14, 0), unit, 0, 0);
  check_clip("octagon (45 degrees)",
             rotated(unit, M_PI / 4, {{0.5, 0.5}}),
             unit,
             2 * (std::sqrt(2.) - 1),
             8);
  check_clip("clip polygon with a repeated vertex (an edge of length 0)",
             square(0.5, 0.5),
             {{{0, 0}}, {{1, 0}}, {{1, 0}}, {{1, 1}}, {{0, 1}}},
             0.25,
             4);
  check_clip("cut through two vertices",
             {{{0, 0}}, {{1, 1}}, {{-1, 1}}},
             unit,
             0.5,
             3);
  {
    // x^2 y^2 over [0.5, 1]^2: (7/24)^2
    double integral = 0;
    for (const auto &t :
         triangulate(clip_polygon(square(0.5, 0.5), unit, tolerance)))
      {
        const double a = signed_area(Poly(t.begin(), t.end()));
        for (const auto &[b, w] : triangle_rule())
          {
            const double x = b[0] * t[0][0] + b[1] * t[1][0] + b[2] * t[2][0];
            const double y = b[0] * t[0][1] + b[1] * t[1][1] + b[2] * t[2][1];
            integral += a * w * x * x * y * y;
          }
      }
    check_close("x^2 y^2 over the quarter overlap",
                integral,
                (7. / 24) * (7. / 24),
                1e-15);
  }

  // 3. a face in the plane z = 0.5 x + 0.2 y, projected onto that plane
  {
    const auto lift = [](const double x, const double y) {
      Vec3<double> v;
      v[0] = x;
      v[1] = y;
      v[2] = 0.5 * x + 0.2 * y + 3;
      return v;
    };
    const std::array<Vec3<double>, 4> face{
      {lift(0, 0), lift(2, 0.1), lift(-0.2, 1), lift(1.7, 1.4)}};
    Vec3<double> normal;
    normal[0] = -0.5;
    normal[1] = -0.2;
    normal[2] = 1;
    normal /= normal.norm();
    const Plane<double> plane(lift(0.5, 0.5), normal);
    // the exact area: the projected area in (x, y) over the cosine
    const Poly   xy{{{0, 0}}, {{2, 0.1}}, {{1.7, 1.4}}, {{-0.2, 1}}};
    const double exact = signed_area(xy) / normal[2];
    check_close("tilted face: area in the plane",
                signed_area(project_face(plane, face)),
                exact,
                1e-13);
    const auto back = plane.point(plane.project(face[3]));
    check_close("tilted face: a vertex mapped back",
                (back - face[3]).norm(),
                0,
                1e-14);
  }

  // 4. projection onto a warped face along a direction, and derivatives
  {
    std::array<Vec3<double>, 4> x;
    const double                coords[4][3] = {{0, 0, 0},
                                                {1.1, 0, 0.1},
                                                {0, 0.9, -0.05},
                                                {1, 1.2, 0.3}};
    for (unsigned int a = 0; a < 4; ++a)
      for (unsigned int d = 0; d < 3; ++d)
        x[a][d] = coords[a][d];
    Vec3<double> n;
    n[0] = 0.1;
    n[1] = -0.2;
    n[2] = 1;
    n /= n.norm();
    const double       xi0 = 0.3, eta0 = 0.8, alpha0 = 0.25;
    const Vec3<double> p = interpolate(x, xi0, eta0) - alpha0 * n;
    double             xi, eta, alpha;
    check_true("projection converges",
               project_along_direction(x, p, n, xi, eta, alpha));
    check_close("projection recovers (xi, eta, alpha)",
                std::abs(xi - xi0) + std::abs(eta - eta0) +
                  std::abs(alpha - alpha0),
                0,
                1e-13);

    // d(xi, eta, alpha) / d(x_3[2]) and d/d(p[0]): AD against differences
    using AD = Sacado::Fad::DFad<double>;
    std::array<Vec3<AD>, 4> xa;
    Vec3<AD>                pa, na;
    for (unsigned int a = 0; a < 4; ++a)
      for (unsigned int d = 0; d < 3; ++d)
        xa[a][d] = x[a][d];
    for (unsigned int d = 0; d < 3; ++d)
      {
        pa[d] = p[d];
        na[d] = n[d];
      }
    xa[3][2]       = AD(2, 0, x[3][2]);
    pa[0]          = AD(2, 1, p[0]);
    const auto   r = projection_with_derivatives(xa, pa, na, xi, eta, alpha);
    double       largest = 0;
    const double h       = 1e-6;
    for (unsigned int k = 0; k < 2; ++k)
      {
        double plus[3], minus[3];
        for (const int sign : {1, -1})
          {
            auto         xs = x;
            Vec3<double> ps = p;
            (k == 0 ? xs[3][2] : ps[0]) += sign * h;
            double a, b, c;
            project_along_direction(xs, ps, n, a, b, c);
            double *out = sign > 0 ? plus : minus;
            out[0]      = a;
            out[1]      = b;
            out[2]      = c;
          }
        for (unsigned int i = 0; i < 3; ++i)
          largest =
            std::max(largest,
                     std::abs(r[i].dx(k) - (plus[i] - minus[i]) / (2 * h)));
      }
    check_close("projection: AD derivatives against central differences",
                largest,
                0,
                1e-8);

    // the clip area of a unit square and a square moved by (s, s) is
    // (1 - s)^2: its derivative -2 (1 - s)
    const double s = 0.3;
    Polygon<AD>  moved, fixed;
    for (const auto &v : square(s, s))
      moved.push_back({{AD(2, 0, v[0]), AD(2, 1, v[1])}});
    for (const auto &v : unit)
      fixed.push_back({{AD(v[0]), AD(v[1])}});
    // every vertex moves with the same two variables
    const AD area = signed_area(clip_polygon(moved, fixed, tolerance));
    check_close("clip area", area.val(), (1 - s) * (1 - s), 1e-14);
    check_close("clip area: derivative by x and y",
                std::abs(area.dx(0) + (1 - s)) + std::abs(area.dx(1) + (1 - s)),
                0,
                1e-14);
  }

  // 6. nodal normals: at a cube's corner the three face normals average
  // to (1, 1, 1) / sqrt 3; on a flat face every corner has its normal
  {
    std::array<Vec3<double>, 4> xy, yz, zx;
    const double                corner[4][2] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
    for (unsigned int a = 0; a < 4; ++a)
      {
        // faces of the unit cube through (1, 1, 1), oriented outward
        xy[a][0] = corner[a][0];
        xy[a][1] = corner[a][1];
        xy[a][2] = 1;
        yz[a][0] = 1;
        yz[a][1] = corner[a][0];
        yz[a][2] = corner[a][1];
        zx[a][0] = corner[a][1];
        zx[a][1] = 1;
        zx[a][2] = corner[a][0];
      }
    const Vec3<double> n = averaged_normal<double>(
      {corner_normal(xy, 3), corner_normal(yz, 3), corner_normal(zx, 3)});
    check_close("cube corner: averaged normal",
                std::abs(n[0] - 1 / std::sqrt(3.)) +
                  std::abs(n[1] - 1 / std::sqrt(3.)) +
                  std::abs(n[2] - 1 / std::sqrt(3.)),
                0,
                1e-15);
    double flat = 0;
    for (unsigned int a = 0; a < 4; ++a)
      flat = std::max(flat, std::abs(corner_normal(xy, a)[2] - 1));
    check_close("flat face: every corner normal", flat, 0, 1e-15);
  }

  // 5. the dual basis
  {
    std::array<Vec3<double>, 4> sq, trapezoid;
    const double                s[4][2] = {{0, 0}, {2, 0}, {0, 2}, {2, 2}};
    const double t[4][2] = {{0, 0}, {3, 0.2}, {0.4, 1.5}, {2.2, 1.9}};
    for (unsigned int a = 0; a < 4; ++a)
      for (unsigned int d = 0; d < 2; ++d)
        {
          sq[a][d]        = s[a][d];
          trapezoid[a][d] = t[a][d];
        }
    const auto   a           = dual_coefficients(face_points(sq));
    const double exact[4][4] = {{4, -2, -2, 1},
                                {-2, 4, 1, -2},
                                {-2, 1, 4, -2},
                                {1, -2, -2, 4}};
    double       error       = 0;
    for (unsigned int j = 0; j < 4; ++j)
      for (unsigned int k = 0; k < 4; ++k)
        error = std::max(error, std::abs(a[j][k] - exact[j][k]));
    check_close("dual basis of a square: closed form", error, 0, 1e-13);

    const auto b = dual_coefficients(face_points(trapezoid));
    const auto e = dual_basis_errors(b, 0, 1, 0, 1, [&](double xi, double eta) {
      const auto tg = tangents(trapezoid, xi, eta);
      return cross(tg[0], tg[1]).norm();
    });
    check_close("dual basis of a distorted face: biorthogonal (5 x 5 Gauss)",
                e.biorthogonality,
                0,
                1e-13);
    check_close("dual basis: sum of psi is 1", e.unity, 0, 1e-13);
  }
}
