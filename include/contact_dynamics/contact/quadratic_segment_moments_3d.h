// The mortar segments of two 9-node faces and their moments
// (quadratic_segment_3d.h has the faces' geometry and the Newton
// projections): the primary face's edges projected onto the secondary
// face, clipped to it, split into triangles from the centroid, and
// integrated on the curved faces.
#ifndef contact_dynamics_contact_quadratic_segment_moments_3d_h
#define contact_dynamics_contact_quadratic_segment_moments_3d_h

#include <contact_dynamics/contact/quadratic_segment_3d.h>

#include <algorithm>
#include <vector>

namespace ContactDynamics
{
  namespace QuadraticSegment3D
  {
    /**
     * A corner of a segment: its coordinates in the secondary face and
     * (a first guess of its projection) in the primary face.
     */
    template <typename Number>
    struct Corner
    {
      std::array<Number, 2> s;
      std::array<double, 2> p;
    };

    /**
     * Clips the polygon to coordinate `axis` >= bound (side = 1) or <=
     * bound (side = -1), Sutherland and Hodgman (any polygon against a
     * convex window). Points on the bound (within 1e-7) are placed on it
     * exactly: a segment's edge on the secondary face's edge does not move.
     */
    template <typename Number>
    std::vector<Corner<Number>>
    clip(const std::vector<Corner<Number>> &polygon,
         const unsigned int                 axis,
         const double                       bound,
         const double                       side)
    {
      // (a primary edge that runs along the secondary face's edge within
      // the iterates' noise is on it: cut there, the cut point would
      // move by 1 / distance, and Newton stalled on the patch test)
      constexpr double tolerance = 1e-7;
      const auto       inside    = [&](const Corner<Number> &c) {
        return side * (value_of(c.s[axis]) - bound) >= -tolerance;
      };
      const auto on_bound = [&](const Corner<Number> &c) {
        return std::abs(value_of(c.s[axis]) - bound) < tolerance;
      };
      const auto cut = [&](const Corner<Number> &a, const Corner<Number> &b) {
        const Number t =
          (bound - a.s[axis]) / (b.s[axis] - a.s[axis]); // (a, b apart)
        Corner<Number> c;
        for (unsigned int k = 0; k < 2; ++k)
          {
            c.s[k] = a.s[k] + t * (b.s[k] - a.s[k]);
            c.p[k] = a.p[k] + value_of(t) * (b.p[k] - a.p[k]);
          }
        c.s[axis] = Number(bound);
        return c;
      };
      std::vector<Corner<Number>> result;
      for (unsigned int k = 0; k < polygon.size(); ++k)
        {
          const auto &a = polygon[k], &b = polygon[(k + 1) % polygon.size()];
          // (a corner on the bound, within the tolerance, is the cut
          // itself: a cut there would extrapolate along the edge)
          if (inside(b))
            {
              if (!inside(a) && !on_bound(b))
                result.push_back(cut(a, b));
              result.push_back(b);
              if (on_bound(b))
                result.back().s[axis] = Number(bound);
            }
          else if (inside(a) && !on_bound(a))
            result.push_back(cut(a, b));
        }
      return result;
    }

    using EdgePoints = std::array<unsigned int, 4>;

    /**
     * The segment of the primary face xm on the secondary face xs, as a
     * polygon in the secondary face's coordinates ordered
     * counterclockwise: edge_points[i] points on edge i of xm (around it
     * from (0,0) over (1,0); equally spaced
     * in its coordinates) projected onto xs, clipped to xs; empty if it
     * does not overlap. False if such a point has no closest point on xs.
     */
    template <typename Number>
    bool
    segment_polygon(const Face<Number>          &xs,
                    const Face<Number>          &xm,
                    const EdgePoints            &edge_points,
                    std::vector<Corner<Number>> &polygon)
    {
      const Face<double> xsd = values(xs);
      polygon.clear();
      // around the primary face: its edges (0,0)-(1,0)-(1,1)-(0,1)
      static constexpr double corner[5][2] = {{0., 0.},
                                              {1., 0.},
                                              {1., 1.},
                                              {0., 1.},
                                              {0., 0.}};
      for (unsigned int edge = 0; edge < 4; ++edge)
        for (unsigned int k = 0; k < edge_points[edge]; ++k)
          {
            const double       t    = double(k) / edge_points[edge];
            const double       p[2] = {corner[edge][0] +
                                         t * (corner[edge + 1][0] - corner[edge][0]),
                                       corner[edge][1] +
                                         t * (corner[edge + 1][1] - corner[edge][1])};
            const auto         N    = shape(p[0], p[1]).N;
            const Vec3<Number> x    = combine(xm, N);
            Vec3<double>       pd;
            for (unsigned int d = 0; d < 3; ++d)
              pd[d] = value_of(x[d]);
            // (from the previous point's solution: the next root along
            // the edge, not a spurious one of the face's extension; else
            // from the tangent plane's)
            const auto system = [&](const auto &z, auto &r, auto &J) {
              closest_point_system(xsd, pd, z, r, J);
            };
            std::array<double, 2> y =
              polygon.empty() ?
                affine_guess(xsd, pd) :
                std::array<double, 2>{{value_of(polygon.back().s[0]),
                                       value_of(polygon.back().s[1])}};
            if (!newton<2>(system, y, 0.5) &&
                (polygon.empty() ||
                 !newton<2>(system, y = affine_guess(xsd, pd), 0.5)))
              return false;
            Corner<Number> c;
            c.s = refine<Number, 2>(
              [&](const auto &z, auto &r, auto &J) {
                closest_point_system(xs, x, z, r, J);
              },
              y);
            c.p = {{p[0], p[1]}};
            polygon.push_back(c);
          }
      double area = 0;
      for (unsigned int k = 0; k < polygon.size(); ++k)
        {
          const auto &a = polygon[k].s,
                     &b = polygon[(k + 1) % polygon.size()].s;
          area +=
            value_of(a[0]) * value_of(b[1]) - value_of(b[0]) * value_of(a[1]);
        }
      if (area < 0)
        std::reverse(polygon.begin(), polygon.end());
      for (const unsigned int axis : {0u, 1u})
        for (const double side : {1., -1.})
          if (!polygon.empty())
            polygon = clip(polygon, axis, side > 0 ? 0. : 1., side);
      return true;
    }

    /**
     * The centroid of a polygon in the secondary face's coordinates (and
     * the mean of its corners' primary guesses); false if its area is
     * nil.
     */
    template <typename Number>
    bool
    centroid(const std::vector<Corner<Number>> &polygon, Corner<Number> &centre)
    {
      Number a = 0., cx = 0., cy = 0.;
      for (unsigned int k = 0; k < polygon.size(); ++k)
        {
          const auto  &p = polygon[k], &q = polygon[(k + 1) % polygon.size()];
          const Number w = p.s[0] * q.s[1] - q.s[0] * p.s[1];
          a += w;
          cx += (p.s[0] + q.s[0]) * w;
          cy += (p.s[1] + q.s[1]) * w;
        }
      if (std::abs(value_of(a)) < 1e-14)
        return false;
      centre.s = {{cx / (3. * a), cy / (3. * a)}};
      centre.p = {{0., 0.}};
      for (const auto &p : polygon)
        for (unsigned int d = 0; d < 2; ++d)
          centre.p[d] += p.p[d] / polygon.size();
      return true;
    }

    /**
     * The moments of a segment, index by index: G_j = int N_j g (0 to 8),
     * D_j = int N_j (9 to 17), M_jk = int N_j N_k for j <= k (18 to 62)
     * and, with velocities, R_j = int N_j (v_s - v_m) . n (63 to 71), over
     * the secondary face's part that the primary face covers, g = (x_m -
     * x_s) . n along the secondary face's unit normal n; with `coupling`,
     * P_lk = int N_l N_k^primary in (*coupling)[9 l + k]. False where a
     * point has no projection onto the primary face.
     */
    constexpr unsigned int n_gap_moments = 63, n_moments = 72;

    template <typename Number>
    bool
    segment_moments(const Face<Number>            &xs,
                    const Face<Number>            &xm,
                    const TriangleRule            &rule,
                    const EdgePoints              &edge_points,
                    const Face<Number>            *vs,
                    const Face<Number>            *vm,
                    std::array<Number, n_moments> &moments,
                    std::array<Number, 81>        *coupling = nullptr)
    {
      moments.fill(Number(0.));
      if (coupling != nullptr)
        coupling->fill(Number(0.));
      std::vector<Corner<Number>> polygon;
      if (!segment_polygon(xs, xm, edge_points, polygon))
        return false;
      const Face<double> xmd = values(xm);
      if (polygon.size() < 3)
        return true;
      // a fan from the polygon's centroid: a corner that appears or
      // disappears as the faces move changes a sliver of it only (a fan
      // from a corner changed the whole triangulation, and with it the
      // rule's error: Newton stalled)
      Corner<Number> centre;
      if (!centroid(polygon, centre))
        return true;
      for (unsigned int k = 0; k < polygon.size(); ++k)
        {
          const Corner<Number> *c[3] = {&centre,
                                        &polygon[k],
                                        &polygon[(k + 1) % polygon.size()]};
          const Number          area =
            0.5 * ((c[1]->s[0] - c[0]->s[0]) * (c[2]->s[1] - c[0]->s[1]) -
                   (c[2]->s[0] - c[0]->s[0]) * (c[1]->s[1] - c[0]->s[1]));
          if (std::abs(value_of(area)) < 1e-14)
            continue;
          for (const auto &[bary, w] : rule)
            {
              std::array<Number, 2> q;
              std::array<double, 3> y{{0., 0., 0.}};
              for (unsigned int a = 0; a < 2; ++a)
                {
                  q[a] = bary[0] * c[0]->s[a] + bary[1] * c[1]->s[a] +
                         bary[2] * c[2]->s[a];
                  y[a] = bary[0] * c[0]->p[a] + bary[1] * c[1]->p[a] +
                         bary[2] * c[2]->p[a];
                }
              const auto s = shape(q[0], q[1]);
              const auto x = combine(xs, s.N);
              const auto normal =
                cross(combine(xs, s.dN[0]), combine(xs, s.dN[1]));
              const Number       J = norm(normal);
              const Vec3<Number> n = normal / J;
              Vec3<double>       xd, nd;
              for (unsigned int d = 0; d < 3; ++d)
                xd[d] = value_of(x[d]), nd[d] = value_of(n[d]);
              if (!newton<3>(
                    [&](const auto &z, auto &r, auto &A) {
                      ray_system(xmd, xd, nd, z, r, A);
                    },
                    y,
                    0.5))
                return false;
              const auto z = refine<Number, 3>(
                [&](const auto &v, auto &r, auto &A) {
                  ray_system(xm, x, n, v, r, A);
                },
                y);
              const Number weight = (w * area) * J;
              const Number gw     = z[2] * weight;
              for (unsigned int j = 0, jk = 18; j < 9; ++j)
                {
                  const Number Nw = s.N[j] * weight;
                  moments[j] += s.N[j] * gw;
                  moments[9 + j] += Nw;
                  for (unsigned int k = j; k < 9; ++k, ++jk)
                    moments[jk] += Nw * s.N[k];
                }
              if (vs == nullptr && coupling == nullptr)
                continue;
              const auto Nm = shape(z[0], z[1]).N;
              if (coupling != nullptr)
                for (unsigned int l = 0; l < 9; ++l)
                  {
                    const Number Nw = s.N[l] * weight;
                    for (unsigned int k = 0; k < 9; ++k)
                      (*coupling)[9 * l + k] += Nw * Nm[k];
                  }
              if (vs == nullptr)
                continue;
              const auto   v_rel = combine(*vs, s.N) - combine(*vm, Nm);
              const Number v_n   = v_rel * n;
              for (unsigned int j = 0; j < 9; ++j)
                moments[n_gap_moments + j] += s.N[j] * v_n * weight;
            }
        }
      return true;
    }
  } // namespace QuadraticSegment3D
} // namespace ContactDynamics

#endif
