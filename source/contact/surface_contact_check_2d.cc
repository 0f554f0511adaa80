// The 2-D passage of a secondary node through a primary face: the swept
// path of the node relative to the moving face, exactly (a quadratic).
#include <contact_dynamics/contact/face_passage.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

namespace ContactDynamics
{
  namespace
  {
    // 2-D cross product
    template <int dim>
    double
    cross(const Tensor<1, dim> &a, const Tensor<1, dim> &b)
    {
      return a[0] * b[1] - a[1] * b[0];
    }

    // A point moves linearly from x0 to x1 during the step, a face from
    // (a0, b0) to (a1, b1), all ends linearly. True if the point passes
    // through the face (not only its line) from the outer side (the side
    // of the normal, the tangent b - a turned clockwise) to the inner side.
    template <int dim>
    bool
    crosses_face(const Point<dim> &x0,
                 const Point<dim> &x1,
                 const Point<dim> &a0,
                 const Point<dim> &a1,
                 const Point<dim> &b0,
                 const Point<dim> &b1)
    {
      // h(s) = n(s).(x(s) - a(s)) |t(s)| = cross(r(s), t(s)) is quadratic
      // in s, with r = x - a, t = b - a
      const Tensor<1, dim> r0 = x0 - a0, dr = (x1 - a1) - r0;
      const Tensor<1, dim> t0 = b0 - a0, dt = (b1 - a1) - t0;
      const double         c0 = cross(r0, t0);
      const double         c1 = cross(r0, dt) + cross(dr, t0);
      const double         c2 = cross(dr, dt);
      if (!(c0 >= 0 && c0 + c1 + c2 < 0))
        return false;
      std::vector<double> roots;
      if (c2 == 0)
        roots.push_back(-c0 / c1); // c1 != 0: h changes sign
      else
        {
          const double discriminant = c1 * c1 - 4 * c2 * c0;
          if (discriminant < 0)
            return false;
          const double q =
            -0.5 * (c1 + (c1 >= 0 ? 1. : -1.) * std::sqrt(discriminant));
          roots.push_back(q / c2);
          if (q != 0)
            roots.push_back(c0 / q);
        }
      for (const double s : roots)
        if (s >= 0 && s <= 1)
          {
            const Tensor<1, dim> r = r0 + s * dr, t = t0 + s * dt;
            const double         xi = r * t / (t * t);
            if (xi >= -1e-10 && xi <= 1 + 1e-10)
              return true;
          }
      return false;
    }
  } // namespace

  std::string
  passage_through_face(const ContactSurface<2>      &f,
                       const std::set<unsigned int> &faces,
                       const Point<2>               &x0,
                       const Point<2>               &x1,
                       const VectorType             &committed_u,
                       const VectorType             &u,
                       const double                  tolerance)
  {
    for (const unsigned int e : faces)
      {
        const unsigned int a = f.faces[e][0], b = f.faces[e][1];
        const Point<2>     a1 = f.position(a, u), b1 = f.position(b, u);
        if (!crosses_face(x0,
                          x1,
                          f.position(a, committed_u),
                          a1,
                          f.position(b, committed_u),
                          b1))
          continue;
        const double length = a1.distance(b1);
        const double depth =
          -cross(x1 - a1, b1 - a1) / std::max(length, 1e-300);
        if (depth <= std::max(tolerance, 1e-2 * length))
          continue;
        std::ostringstream passage;
        passage << "went through the primary face from (" << a1[0] << ", "
                << a1[1] << ") to (" << b1[0] << ", " << b1[1]
                << ") in this step and ends " << depth
                << " behind it, but its contact condition is not active";
        return passage.str();
      }
    return {};
  }



  Tensor<1, 2>
  outward_normal(const ContactSurface<2> &surface,
                 const unsigned int       node,
                 const VectorType        &u)
  {
    // (the tangent b - a turned clockwise, as in crosses_face())
    Tensor<1, 2> n;
    for (const unsigned int f : surface.node_faces[node])
      {
        const Tensor<1, 2> t = surface.position(surface.faces[f][1], u) -
                               surface.position(surface.faces[f][0], u);
        n += Tensor<1, 2>({t[1], -t[0]}) / t.norm();
      }
    return n / n.norm();
  }

  double
  depth_behind_surface(const ContactSurface<2>      &surface,
                       const std::set<unsigned int> &faces,
                       const Point<2>               &x,
                       const VectorType             &u)
  {
    double signed_distance = std::numeric_limits<double>::quiet_NaN();
    for (const unsigned int e : faces)
      {
        const Point<2>     a  = surface.position(surface.faces[e][0], u);
        const Tensor<1, 2> t  = surface.position(surface.faces[e][1], u) - a;
        const double       xi = (x - a) * t / (t * t);
        if (xi < -1e-10 || xi > 1 + 1e-10)
          continue;
        const double d = cross(x - a, t) / t.norm();
        if (!(std::abs(d) >= std::abs(signed_distance)))
          signed_distance = d;
      }
    return -signed_distance;
  }
} // namespace ContactDynamics
